#!/usr/bin/env python3
"""docs/reference.md's input tables, generated from the loaders' own tables.

`touchdown schema --json` lists every block of every input file as its loader reads it: the keys
in order, each key's unit (from its suffix) and, for the keys read from a number table, the range
the loader accepts and the default it takes. This script rewrites each `<!-- fields: ID -->` table
of docs/reference.md from that: one row per key, the unit, range and default columns from the
code, the meaning (and the default of a key the code has no number table for) kept from the
table as it was, and a `Read by` line naming the source file. A block the code has and the
reference lacks, a key without a meaning, or a table whose id the code does not know is an error.

  python3 tools/reference_tables.py --touchdown build/apps/touchdown           # rewrite the tables
  python3 tools/reference_tables.py --touchdown build/apps/touchdown --check   # exit 1 if out of date

tests/python/test_reference.py runs the check (CTest `python_reference`)."""
import argparse
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MARKER = re.compile(r"<!-- fields: (\S+) -->")
HEADER = "| field | unit | range | default | meaning |"


def schema(touchdown):
    done = subprocess.run([touchdown, "schema", "--json"], capture_output=True, text=True, check=True)
    return {block["id"]: block for block in json.loads(done.stdout)}


def _cells(line):
    """A table row's cells, `\\|` kept inside a cell."""
    return [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]


def _escape(text):
    return text.replace("|", "\\|")


def _old_rows(table_lines):
    """{key: {column: text}} of an existing table (a cell naming several keys gives each its row)."""
    if not table_lines:
        return {}
    columns = _cells(table_lines[0])
    rows = {}
    for line in table_lines[2:]:
        cells = dict(zip(columns, _cells(line)))
        for key in re.findall(r"`([^`]+)`", cells.get(columns[0], "")):
            rows[key] = cells
    return rows


def render(block, old, problems):
    lines = [HEADER, "|---|---|---|---|---|"]
    for k in block["keys"]:
        was = old.get(k["key"], {})
        default = k["default"] or was.get("default", "") or "-"
        meaning = was.get("meaning", "")
        if not meaning:
            problems.append(f"table {block['id']}: key `{k['key']}` has no meaning")
        lines.append(f"| `{k['key']}` | {k['unit']} | {_escape(k['range'] or '-')} | {_escape(default)} | {meaning} |")
    return lines + ["", f"Read by `{block['read_by']}`."]


def regenerate(text, blocks):
    """(the reference with its input tables regenerated, problems)."""
    lines, out, problems, seen = text.split("\n"), [], [], set()
    i = 0
    while i < len(lines):
        line = lines[i]
        out.append(line)
        i += 1
        marker = MARKER.fullmatch(line.strip())
        if not marker:
            continue
        table_id = marker.group(1)
        if table_id not in blocks:
            problems.append(f"table {table_id}: no such block in `touchdown schema`")
            continue
        seen.add(table_id)
        table = []
        while i < len(lines) and lines[i].startswith("|"):
            table.append(lines[i])
            i += 1
        if i + 1 < len(lines) and lines[i] == "" and lines[i + 1].startswith("Read by `"):
            i += 2
        out.extend(render(blocks[table_id], _old_rows(table), problems))
    for missing in sorted(set(blocks) - seen):
        problems.append(f"block {missing}: docs/reference.md has no `<!-- fields: {missing} -->` table")
    return "\n".join(out), problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--touchdown", default=os.path.join(ROOT, "build", "apps", "touchdown"))
    parser.add_argument("--reference", default=os.path.join(ROOT, "docs", "reference.md"))
    parser.add_argument("--check", action="store_true", help="change nothing; exit 1 if the tables are out of date")
    args = parser.parse_args()
    with open(args.reference, encoding="utf-8") as f:
        text = f.read()
    new, problems = regenerate(text, schema(args.touchdown))
    for p in problems:
        print(f"{args.reference}: {p}", file=sys.stderr)
    if args.check:
        if new != text:
            print(f"{args.reference}: input tables out of date; run python3 tools/reference_tables.py", file=sys.stderr)
        return 1 if new != text or problems else 0
    if new != text:
        tmp = args.reference + ".tmp"
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(new)
        os.replace(tmp, args.reference)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Which functions' floating-point code differs between two builds of one binary.

    tools/fp_code_diff.py OLD_BINARY NEW_BINARY

For a build change meant to leave every result alone (a compile option of code that only parses
options or converts objects, say): disassembles both binaries (objdump), compares each function's
instructions with addresses and PLT indirections taken out, and lists the functions whose code
differs and that do floating-point arithmetic. Without -ffast-math the compiler neither reorders
nor regroups floating-point operations, so two versions of a function round alike unless one of
them fuses a multiply and an add (FMA) the other does not. The verdict: exit 0 when no differing
function holds an FMA instruction (the listed ones, plain operations each rounded once, are for
review); 1 when one does, so the change may move results at rounding level
(tools/golden_outputs.sh then shows whether it does on the golden jobs).
"""
import re
import subprocess
import sys

FMA = re.compile(r"^v?fn?m(add|sub)|^vfmaddsub|^vfmsubadd")
FP_ARITHMETIC = re.compile(r"^v?(add|sub|mul|div|sqrt|min|max|fmadd|fmsub|fnmadd|fnmsub)\w*[sp][sd]$"
                           r"|^v?fn?m(add|sub)|^f(add|sub|mul|div|sqrt)")


def functions(binary):
    """Function name -> its instructions, with addresses and PLT stubs normalised away."""
    listing = subprocess.run(["objdump", "-d", "--no-show-raw-insn", "-M", "intel", binary],
                             capture_output=True, text=True, check=True).stdout
    result, current = {}, None
    for line in listing.splitlines():
        header = re.match(r"^[0-9a-f]+ <(.+)>:$", line)
        if header:
            current = result.setdefault(header.group(1), [])
            continue
        fields = line.split("\t", 1)
        if current is None or not line.startswith(" ") or len(fields) < 2:
            continue
        instruction = re.sub(r"#.*", "", fields[1])
        instruction = re.sub(r"\b[0-9a-f]{4,}\b", "ADDR", instruction).replace("@plt>", ">")
        if "rip" in instruction:
            instruction = re.sub(r"0x[0-9a-f]+", "OFFSET", instruction)
        current.append(instruction.strip())
    return result


def matching(instructions, pattern):
    return [i for i in instructions if i and pattern.match(i.split()[0])]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    old, new = functions(sys.argv[1]), functions(sys.argv[2])
    names = sorted(set(old) | set(new))
    differing = [n for n in names if old.get(n) != new.get(n)]
    print(f"{len(old)} and {len(new)} functions, {len(differing)} differ or are in one only")
    fused = 0
    for name in differing:
        fma = [len(matching(f.get(name, []), FMA)) for f in (old, new)]
        arithmetic = [len(matching(f.get(name, []), FP_ARITHMETIC)) for f in (old, new)]
        if any(fma):
            fused += 1
            print(f"FMA       old {fma[0]:4d} new {fma[1]:4d}  {name}")
        elif any(arithmetic):
            print(f"plain FP  old {arithmetic[0]:4d} new {arithmetic[1]:4d}  {name}")
    print(f"differing functions with FMA instructions: {fused}")
    return 1 if fused else 0


if __name__ == "__main__":
    sys.exit(main())

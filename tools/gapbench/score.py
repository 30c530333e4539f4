#!/usr/bin/python3
"""gapbench scorer: what `touchdown diagnose` named against what each set hid.

  /usr/bin/python3 tools/gapbench/score.py SETS_DIR OUT_DIR

SETS_DIR: generate.py's OUT_DIR (holding sets/) or its sets/ folder (truth.yaml per set).
OUT_DIR: run_matrix.sh's OUT_DIR (OUT/<set>/diagnose/diagnosis.json, OUT/<set>/status.csv).
Writes OUT_DIR/score.md (Markdown tables), OUT_DIR/score.csv (the same numbers, long form) and
OUT_DIR/score_per_set.csv (one row per set), and prints score.md.

Per set (library effects hidden): named = the hidden effect is among the named ones; missed = nothing
named; wrong = a library effect other than the hidden one named. Per control: falsely named = anything
named. `weaker_dynamic_term` is never counted (not a soil effect), nor is a nuisance the workflow
reports under a separate heading (any diagnosis.json key holding "nuisance", or sensor/measurement
terms reported apart), except that on a sensor_offset set a sensor_offset reported there counts as
named. Coverage: of the sets whose hidden effect was named, the fraction where every fitted parameter's
95 % interval holds the true value (intervals from diagnosis.json `effect_parameters`, else from
model.yaml's `interval_95`). Rates are over the sets diagnose finished; failures are counted apart.
"""
import csv
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _deps  # noqa: F401,E402

import yaml  # noqa: E402

LIBRARY = ["inertial_drag", "rate_damping", "added_mass", "added_mass_plug", "compaction_peak",
           "depth_exponent", "gas_cushion", "sensor_offset"]
NOT_COUNTED = {"weaker_dynamic_term", "none", ""}
PARAM_KEYS = {"inertial_drag": ["lambda"], "rate_damping": ["c_N_s_m3"], "added_mass": ["c_a"],
              "added_mass_plug": ["c_p"], "compaction_peak": ["k_c_kg_m3", "d_c_mm"], "depth_exponent": ["p"],
              "gas_cushion": ["chi", "c_g_N_s_m3"], "sensor_offset": ["dz_mm", "dt_ms"]}


# ---------------------------------------------------------------------------------------------
# Reading diagnosis.json tolerantly

def as_names(x):
    """A list of effect ids from a string ('a+b', 'a, b', 'none'), a list, or dicts with an id."""
    out = []
    if x is None:
        return out
    if isinstance(x, str):
        for part in re.split(r"[+,;\s]+", x.strip()):
            if part and part.lower() != "none":
                out.append(part)
        return out
    if isinstance(x, (list, tuple)):
        for e in x:
            out += as_names(e)
        return out
    if isinstance(x, dict):
        for k in ("id", "effect", "name", "term"):
            if isinstance(x.get(k), str):
                return as_names(x[k])
        # a mapping effect -> something
        return [k for k in x if k in LIBRARY or k == "weaker_dynamic_term"]
    return out


def named_from(diag):
    """(named soil effects in order, nuisance effects reported apart)."""
    named = []
    for key in ("named_effects", "named_effect"):
        if key in diag:
            named = as_names(diag[key])
            if named or key == "named_effect":
                break
    nuis = []
    for k, v in diag.items():
        kl = k.lower()
        if "nuisance" in kl or kl in ("sensor_terms", "measurement_terms", "named_nuisances", "nuisances"):
            nuis += as_names(v)
    seen = []
    for n in named:
        if n not in seen:
            seen.append(n)
    return seen, sorted(set(nuis))


INTERVAL_KEYS = ("interval_95", "interval95", "ci95", "ci_95", "interval", "ci", "confidence_interval")


def _interval_of(obj):
    if isinstance(obj, dict):
        for k in INTERVAL_KEYS:
            v = obj.get(k)
            if isinstance(v, (list, tuple)) and len(v) == 2 and all(isinstance(x, (int, float)) for x in v):
                return float(v[0]), float(v[1])
        for lo, hi in (("low", "high"), ("lower", "upper"), ("lo", "hi"), ("min", "max"),
                       ("interval_95_low", "interval_95_high")):
            if isinstance(obj.get(lo), (int, float)) and isinstance(obj.get(hi), (int, float)):
                return float(obj[lo]), float(obj[hi])
    if isinstance(obj, (list, tuple)) and len(obj) == 2 and all(isinstance(x, (int, float)) for x in obj):
        return float(obj[0]), float(obj[1])
    return None


def intervals_from_diagnosis(diag):
    """{(effect, param): (lo, hi)} from `effect_parameters`, whatever its nesting."""
    out = {}
    ep = diag.get("effect_parameters")

    def visit(obj, path):
        iv = _interval_of(obj)
        if iv is not None and path:
            key = ".".join(path)
            parts = key.split(".")
            eff = next((p for p in parts if p in PARAM_KEYS or p == "weaker_dynamic_term"), None)
            par = None
            if eff is not None:
                for p in parts[parts.index(eff) + 1:]:
                    if p not in INTERVAL_KEYS and p not in ("value", "parameters"):
                        par = p
                        break
            if eff and par:
                out[(eff, par)] = iv
        if isinstance(obj, dict):
            # an interval map beside the values: {param: [lo, hi]}
            for k in INTERVAL_KEYS:
                if isinstance(obj.get(k), dict):
                    for p, v in obj[k].items():
                        iv2 = _interval_of(v)
                        if iv2 is not None:
                            visit(v, path + [p])
            for k, v in obj.items():
                if k in INTERVAL_KEYS:
                    continue
                if isinstance(v, (dict, list)):
                    visit(v, path + [str(k)])
        elif isinstance(obj, list):
            for e in obj:
                if isinstance(e, dict):
                    sub = []
                    for k in ("effect", "term", "id"):
                        if isinstance(e.get(k), str):
                            sub.append(e[k])
                            break
                    for k in ("parameter", "param", "name", "key"):
                        if isinstance(e.get(k), str):
                            sub += e[k].split(".")
                            break
                    visit(e, path + sub)
    if ep is not None:
        visit(ep, [])
    return out


def intervals_from_model(path):
    out = {}
    try:
        with open(path) as f:
            m = yaml.safe_load(f) or {}
    except (OSError, yaml.YAMLError):
        return out
    for eff, body in (m.get("effects") or {}).items():
        if isinstance(body, dict) and isinstance(body.get("interval_95"), dict):
            for p, iv in body["interval_95"].items():
                iv2 = _interval_of(iv)
                if iv2:
                    out[(eff, p)] = iv2
    return out


def intervals_from_rig(diag):
    """{(effect, param): (lo, hi)} from `rig_parameters` ({"effect.param": {interval_95: ...}}):
    the rig's fitted terms, which diagnose reports apart from the soil's."""
    out = {}
    for key, body in (diag.get("rig_parameters") or {}).items():
        eff, _, par = key.partition(".")
        iv = _interval_of(body)
        if par and iv is not None:
            out[(eff, par)] = iv
    return out


def true_value(truth, hidden, p):
    """The value a hidden effect's parameter `p` has in the data. For a sensor offset's dt the
    definition (docs/model_gap.md: recorded t = 0 lies dt after the true touchdown) holds the
    set's detector too: each drop's recorded zero lies `recorded_t0_after_true_touchdown_s` after
    its touchdown (the hidden dt plus that drop's detection delay), and the common offset a fit can
    see is their mean; the per-drop rest is drop-to-drop scatter. Sets without that record (raw
    sets, whose importer finds touchdown) keep the hidden value."""
    tv = truth["hidden_effect"].get(p)
    if hidden == "sensor_offset" and p == "dt_ms":
        per_drop = [d["recorded_t0_after_true_touchdown_s"] for d in truth.get("drops") or []
                    if isinstance(d, dict) and d.get("recorded_t0_after_true_touchdown_s") is not None]
        if per_drop:
            return 1e3 * sum(per_drop) / len(per_drop)
    return tv


# ---------------------------------------------------------------------------------------------

def score_set(truth, out_dir):
    name = truth["set"]
    hidden = truth["hidden_effect"]["id"]
    kind = truth["kind"]
    real = truth["realism"]
    row = {"set": name, "form": truth["form"], "kind": kind, "hidden": hidden,
           "size": truth.get("size_factor") or "", "label": truth["label"]}
    st_path = os.path.join(out_dir, name, "status.csv")
    status = "not_run"
    if os.path.exists(st_path):
        with open(st_path) as f:
            rows = list(csv.DictReader(f))
        if rows:
            status = rows[-1].get("status", "unknown")
    dj = os.path.join(out_dir, name, "diagnose", "diagnosis.json")
    diag = None
    if os.path.exists(dj):
        try:
            with open(dj) as f:
                diag = json.load(f)
        except (OSError, ValueError):
            diag = None
            status = "bad_json"
    if diag is not None and status == "not_run":
        status = "ok"
    row["status"] = status if diag is not None or status != "ok" else "no_json"
    row["done"] = int(diag is not None)
    # realism factors
    row["sampling_kind"] = real["sampling_kind"]
    row["load_cell"] = "yes" if real.get("load_cell") else "no"
    row["scatter"] = "zeta scatter >= 2 %" if real["zeta_scatter_sd"] >= 0.02 else "zeta scatter < 2 %"
    row["replicates"] = truth["design"]["replicates"]
    row["sample_rate_hz"] = real["sample_rate_hz"]
    row["detector"] = real.get("detector") or "(importer)"
    row["named"] = row["missed"] = row["wrong"] = row["falsely_named"] = row["covered"] = ""
    row["named_effects"] = row["nuisances"] = row["parameters"] = ""
    if diag is None:
        return row
    named, nuis = named_from(diag)
    soil_named = [n for n in named if n not in NOT_COUNTED and n not in nuis]
    row["named_effects"] = "+".join(named) if named else "none"
    row["nuisances"] = "+".join(nuis)
    if kind == "library":
        hit = hidden in soil_named or (hidden == "sensor_offset" and "sensor_offset" in nuis)
        row["named"] = int(hit)
        row["missed"] = int(not soil_named and not hit)
        row["wrong"] = int(any(n != hidden for n in soil_named))
        if hit:
            ivs = intervals_from_diagnosis(diag)
            if hidden == "sensor_offset":
                ivs.update(intervals_from_rig(diag))
            if not any(e == hidden for (e, _) in ivs):
                ivs.update(intervals_from_model(os.path.join(out_dir, name, "diagnose", "model.yaml")))
            ok = True
            parts = []
            for p in PARAM_KEYS[hidden]:
                tv = true_value(truth, hidden, p)
                iv = ivs.get((hidden, p))
                if tv is None:
                    continue
                if iv is None:
                    ok = False
                    parts.append("%s %g [no interval]" % (p, tv))
                    continue
                inside = iv[0] <= tv <= iv[1]
                ok = ok and inside
                parts.append("%s %g in [%g, %g]: %s" % (p, tv, iv[0], iv[1], "yes" if inside else "no"))
            row["covered"] = int(ok)
            row["parameters"] = "; ".join(parts)
    else:
        row["falsely_named"] = int(bool(soil_named))
    return row


def rate(rows, key):
    vals = [r[key] for r in rows if r[key] != ""]
    if not vals:
        return "", 0
    return sum(vals) / len(vals), len(vals)


def pct(x):
    return "" if x == "" else "%.0f %%" % (100 * x)


def summarise(rows):
    done = [r for r in rows if r["done"]]
    lib = [r for r in done if r["kind"] == "library"]
    ctl = [r for r in done if r["kind"] == "control"]
    named, _ = rate(lib, "named")
    missed, _ = rate(lib, "missed")
    wrong, _ = rate(lib, "wrong")
    false, _ = rate(ctl, "falsely_named")
    cov, ncov = rate(lib, "covered")
    return {"n_sets": len(rows), "n_done": len(done), "n_failed": len(rows) - len(done),
            "n_library": len(lib), "n_control": len(ctl), "named": named, "missed": missed, "wrong": wrong,
            "falsely_named": false, "coverage": cov, "n_coverage": ncov}


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: score.py SETS_DIR OUT_DIR")
    sets_dir, out_dir = sys.argv[1], sys.argv[2]
    if os.path.isdir(os.path.join(sets_dir, "sets")):
        sets_dir = os.path.join(sets_dir, "sets")
    truths = []
    for name in sorted(os.listdir(sets_dir)):
        tp = os.path.join(sets_dir, name, "truth.yaml")
        if os.path.exists(tp):
            with open(tp) as f:
                truths.append(yaml.safe_load(f))
    rows = [score_set(t, out_dir) for t in truths]

    tables = []   # (title, group column name, [(level, summary)])
    by_effect = []
    for eff in LIBRARY:
        for size in (1, 3, 10):
            rs = [r for r in rows if r["kind"] == "library" and r["hidden"] == eff and r["size"] == size]
            if rs:
                by_effect.append(("%s x%d" % (eff, size), summarise(rs)))
    for c in ("none", "floor", "density", "rate_exponent"):
        rs = [r for r in rows if r["kind"] == "control" and r["hidden"] == c]
        if rs:
            by_effect.append(("control: %s" % c, summarise(rs)))
    tables.append(("Per hidden effect and size", "hidden", by_effect))
    for fac, title in (("sampling_kind", "Sampling kind"), ("load_cell", "Load cell dynamics"),
                       ("scatter", "Drop-to-drop zeta scatter"), ("replicates", "Replicates per condition"),
                       ("form", "Form (raw sets go through `touchdown import`)"), ("sample_rate_hz", "Sample rate"),
                       ("detector", "Touchdown detector (dataset form)")):
        levels = sorted({r[fac] for r in rows}, key=lambda x: (str(type(x)), x))
        tables.append((title, fac, [(str(lv), summarise([r for r in rows if r[fac] == lv])) for lv in levels]))
    tables.append(("All sets", "all", [("all", summarise(rows))]))

    cols = ["n_sets", "n_done", "n_failed", "named", "missed", "wrong", "falsely_named", "coverage"]
    md = ["# gapbench score", "",
          "Sets: %d; diagnosed: %d. Rates over diagnosed sets: named / missed / wrong over sets hiding a library "
          "effect, falsely named over controls, coverage over sets whose hidden effect was named." %
          (len(rows), sum(r["done"] for r in rows)), ""]
    csv_rows = []
    for title, fac, entries in tables:
        md += ["## " + title, "", "| %s | sets | diagnosed | failed | named | missed | wrong | falsely named | "
               "interval coverage |" % fac, "|---|---|---|---|---|---|---|---|---|"]
        for level, s in entries:
            cov = "" if s["coverage"] == "" else "%s (%d)" % (pct(s["coverage"]), s["n_coverage"])
            md.append("| %s | %d | %d | %d | %s | %s | %s | %s | %s |" % (
                level, s["n_sets"], s["n_done"], s["n_failed"], pct(s["named"]), pct(s["missed"]),
                pct(s["wrong"]), pct(s["falsely_named"]), cov))
            csv_rows.append([title, level] + [("" if s[c] == "" else (round(s[c], 4) if isinstance(s[c], float)
                                                                     else s[c])) for c in cols])
        md.append("")
    named_on_controls = {}
    for r in rows:
        if r["kind"] == "control" and r["done"] and r["falsely_named"]:
            named_on_controls.setdefault(r["hidden"], []).append(r["named_effects"])
    if named_on_controls:
        md += ["## What was named on controls", ""]
        for c, lst in sorted(named_on_controls.items()):
            md.append("- %s: %s" % (c, ", ".join(sorted(lst))))
        md.append("")
    text = "\n".join(md)
    with open(os.path.join(out_dir, "score.md"), "w") as f:
        f.write(text + "\n")
    with open(os.path.join(out_dir, "score.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["table", "level"] + cols)
        w.writerows(csv_rows)
    keys = ["set", "form", "kind", "hidden", "size", "label", "status", "done", "named_effects", "nuisances",
            "named", "missed", "wrong", "falsely_named", "covered", "parameters", "sampling_kind", "load_cell",
            "scatter", "replicates", "sample_rate_hz", "detector"]
    with open(os.path.join(out_dir, "score_per_set.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    print(text)


if __name__ == "__main__":
    main()

#!/usr/bin/env bash
# The model-gap workflow tried blind on the soils as shipped (docs/model_gap.md, "Blind test on the
# shipped soil"): `touchdown synth` hides each library effect in turn, nothing (control) and the
# out-of-library floor (control) in 12 drops on loose FJS-1 (flat and curved pads, air and vacuum,
# 0.8 / 1.2 / 1.6 m/s), each set twice: generated with the shipped soil's dynamic term, and without
# it (a copy of the soil file with `dynamic_term: false`, its drops then labelled fjs1_lp, as data
# from a medium without the term would come). `touchdown diagnose` runs on each with the shipped
# soil as its base and prints one line per set: the terms forward selection kept, in order, with
# their fitted parameters, whether it said the shipped dynamic term is not supported, and the
# held-out force NRMSE of the base and of the named model (its reduction).
#
#   tools/diagnose_blind_test.sh BUILD_DIR OUT_DIR [instantaneous|period_mean]
#
# The third argument is the sensor sampling of both the synthetic records and diagnose's comparison
# (synth's sensor_sampling, diagnose --sensor-sampling; period_mean by default, as both commands).
# BLIND_EFFECTS and BLIND_TERMS pick rows (default: all effects, with and without the term).
# A few minutes on 2 cores. The hidden effects' sizes can be scaled for a power sweep:
# BLIND_SCALE=0.25 multiplies every hidden parameter's departure from neutral by 0.25.
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
out=$(cd "$2" && pwd)
sampling=${3:-period_mean}
scale=${BLIND_SCALE:-1}
sc() { /usr/bin/python3 -c "import sys; print('%.6g' % (float(sys.argv[1]) + $scale * (float(sys.argv[2]) - float(sys.argv[1]))))" "$1" "$2"; }
source_dir=$(cd "$(dirname "$0")/.." && pwd)
td="$build/apps/touchdown"
export TOUCHDOWN_DATA_DIR="$source_dir/data"
quasi_static="$out/fjs1_lp_without_dynamic_term.yaml"
sed 's/^dynamic_term: true/dynamic_term: false/' "$source_dir/data/soils/fjs1_lp.yaml" > "$quasi_static"
grep -q '^dynamic_term: false' "$quasi_static" || { echo "fjs1_lp.yaml has no 'dynamic_term: true' line" >&2; exit 1; }

hidden() {  # the hidden_effect block of a set (the parameters of tests/drop_tests/gap/diagnose_test.cpp)
  case $1 in
    none) ;;
    # inertial_drag replaces the soil's lambda 1.1: its departure is counted from 1.1.
    inertial_drag) echo "hidden_effect: {id: inertial_drag, lambda: $(sc 1.1 6.0)}" ;;
    rate_damping) echo "hidden_effect: {id: rate_damping, c_N_s_m3: $(sc 0 15000)}" ;;
    added_mass) echo "hidden_effect: {id: added_mass, c_a: $(sc 0 3.0)}" ;;
    added_mass_plug) echo "hidden_effect: {id: added_mass_plug, c_p: $(sc 0 1.0)}" ;;
    compaction_peak) echo "hidden_effect: {id: compaction_peak, k_c_kg_m3: $(sc 0 30000), d_c_mm: 3}" ;;
    depth_exponent) echo "hidden_effect: {id: depth_exponent, p: $(sc 1 1.3)}" ;;
    gas_cushion) echo "hidden_effect: {id: gas_cushion, chi: $(sc 0 0.3), c_g_N_s_m3: $(sc 0 8000)}" ;;
    sensor_offset) echo "hidden_effect: {id: sensor_offset, dz_mm: $(sc 0 1), dt_ms: $(sc 0 3)}" ;;
    cohesion) echo "hidden_effect: {id: cohesion, c_kPa: $(sc 0 1.0)}" ;;
    floor) echo "hidden_effect: {id: floor_stiffening}" ;;
  esac
}

printf '%-26s %-60s %-9s %s\n' "set" "selected terms (parameters)" "no term?" "held-out force NRMSE base -> named (cut)"
for term in ${BLIND_TERMS:-with without}; do
  soil=fjs1_lp
  [ "$term" = without ] && soil="$quasi_static"
  for effect in ${BLIND_EFFECTS:-none inertial_drag rate_damping added_mass added_mass_plug compaction_peak depth_exponent gas_cushion sensor_offset cohesion floor}; do
    name="${effect}_${term}_term"
    cat > "$out/$name.synth.yaml" <<SPEC
schema_version: 1
type: synth
name: blind_$name
seed: 11
sample_rate_hz: 1000
rest_duration_s: 0.008
sensor_sampling: $sampling
drops:
  - pads: [flat, curved]
    soils: [$soil]
    atmospheres: [air, vacuum]
    impact_speeds_m_s: [0.8, 1.2, 1.6]
noise: {force_sigma_N: 0.5, penetration_sigma_mm: 0.01, force_drift_N_s: 1.0, penetration_drift_mm_s: 0.02, force_resolution_N: 0.1, penetration_resolution_mm: 0.005}
$(hidden "$effect")
provenance: {all: "assumption: a blind test of diagnose (tools/diagnose_blind_test.sh)"}
SPEC
    rm -rf "$out/$name" "$out/$name.diagnosis"
    "$td" synth "$out/$name.synth.yaml" --out "$out/$name" > /dev/null
    # Data from a medium without the term still say which soil they were dropped on.
    sed -i "s|$quasi_static|fjs1_lp|" "$out/$name/drops.csv"
    "$td" diagnose "$out/$name" --out "$out/$name.diagnosis" --threads 2 --sensor-sampling "$sampling" > /dev/null 2>&1
    /usr/bin/python3 - "$out/$name.diagnosis/diagnosis.json" "$name" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
name = "+".join(j["selected_terms"]) or "none"
params = " ".join("%s=%.4g" % (k.split(".")[-1], v["value"]) for k, v in j["effect_parameters"].items())
before, after = j["gap_before"]["force_nrmse"], j["gap_after"]["force_nrmse"]
print("%-26s %-60s %-9s %.4f -> %.4f (%.0f %%)" % (sys.argv[2], name + (" (" + params + ")" if params else ""),
      "yes" if "dynamic_term_statement" in j else "no", before, after, 100 * j["gap_reduction"]))
PY
  done
done

#!/usr/bin/env bash
# The shipped calibration of the study's block (data/calibration/study_block.yaml) made again from scratch: the
# eleven CFD runs of examples/calibration/study_block.yaml on 2 ranks (about 3 minutes), then the constants
# compared with the shipped ones (0.5 %: the runs repeat to round-off on the same machine; the margin covers
# another machine's last digits). ctest -L slow -R calibration_study_block
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
chute="${CHUTE_BINARY:-$repo/build/apps/chute}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
mpirun --allow-run-as-root --oversubscribe -np 2 "$chute" calibrate "$repo/examples/calibration/study_block.yaml" \
  --out "$out" > "$out/log" 2>&1 || { tail -20 "$out/log"; exit 1; }
/usr/bin/python3 - "$repo/data/calibration/study_block.yaml" "$out/study_block.yaml" <<'PY'
import sys, yaml
shipped, made = (yaml.safe_load(open(p))["model"] for p in sys.argv[1:3])
def flat(model):  # the sections (slope law, ground effect) as one number per entry
    out = {k: v for k, v in model.items() if not isinstance(v, dict)}
    for section in ("slope", "ground_effect"):
        for k, v in model.get(section, {}).items():
            for i, x in enumerate(v if isinstance(v, list) else [v]):
                out[f"{section}.{k}[{i}]"] = x
    return out
shipped, made = flat(shipped), flat(made)
# 0.5 % of the value, and 1e-4 absolute for the push near zero.
bad = [k for k in shipped if k not in made or abs(made[k] - shipped[k]) > 5e-3 * abs(shipped[k]) + 1e-4]
bad += [k for k in made if k not in shipped]
for k in shipped:
    print(f"{k}: shipped {shipped[k]:.6g}, made {made.get(k, float('nan')):.6g}")
sys.exit(1 if bad else 0)
PY

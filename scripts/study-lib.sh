# Sourced by each scenario's `run` script (examples/<scenario>/run): runs its cases and draws its figure.
#   examples/<scenario>/run [--quick] [--redo] [--out DIR]
# --quick: every case at half the cells each way (domain.refinement 0.5, 10 cells across the block), for a check of
#          the whole chain in a few minutes; results in results/study-quick unless --out is given.
# --redo:  run the cases again even if a finished run is there.
# Runs go to OUT/runs/<case>-<key>, where the key is a hash of the case file's text and the command's settings, so a
# run shared by two scenarios (the free fall and the density sweep's 2500 kg/m^3) is made once and reused until its
# case or settings change. Each scenario lists its runs in OUT/<scenario>/runs.txt (label, folder, wall time) and
# its figures, claims.csv and summary.md go next to it (python/study/figure.py).
# CHUTE_RANKS sets the ranks (default 2 on a machine with 2 cores or more).
set -euo pipefail
study_dir=$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)
study_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scenario=$(basename "$study_dir")
quick=0
redo=0
out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --redo) redo=1 ;;
    --out) out=$2; shift ;;
    *) echo "$scenario/run: unknown option '$1' (--quick, --redo, --out DIR)" >&2; exit 2 ;;
  esac
  shift
done
[ -n "$out" ] || out=$study_root/results/$([ $quick -eq 1 ] && echo study-quick || echo study)
mkdir -p "$out/runs" "$out/$scenario"
out=$(cd "$out" && pwd)
ranks=${CHUTE_RANKS:-$(( $(nproc) > 1 ? 2 : 1 ))}
chute=$study_root/build/apps/chute
[ -x "$chute" ] || { echo "$scenario/run: $chute is missing: run scripts/build.sh first" >&2; exit 2; }
quick_settings=()
[ $quick -eq 1 ] && quick_settings=(--set domain.refinement=0.5)
: > "$out/$scenario/runs.txt.part"

# study_run LABEL CASE [--set key=value ...]: one run of a case of this folder (or a path relative to it), reused
# when finished; its folder is listed under LABEL for the figure.
study_run() {
  local label=$1 case_file=$2
  shift 2
  case "$case_file" in /*) ;; *) case_file=$study_dir/$case_file ;; esac
  [ -f "$case_file" ] || { echo "$scenario/run: no case file $case_file" >&2; exit 2; }
  local key
  key=$( { cat "$case_file"; printf '%s\n' "$@" "${quick_settings[@]}"; } | md5sum | cut -c1-10)
  local dir=$out/runs/$(basename "$(dirname "$case_file")")-$(basename "$case_file" .yaml)-$key
  if [ $redo -eq 1 ] || [ ! -f "$dir/summary.txt" ]; then
    rm -rf "$dir"
    printf '%s: %-18s running %s %s\n' "$scenario" "$label" "${case_file#"$study_root"/}" "$*"
    local start=$SECONDS
    if ! mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$chute" run "$case_file" "$@" \
        "${quick_settings[@]}" --out "$dir" --no-plots > "$dir.log" 2>&1; then
      echo "$scenario/run: the run '$label' failed; its output: $dir.log" >&2
      tail -5 "$dir.log" >&2
      exit 3
    fi
    echo "$(( SECONDS - start ))" > "$dir/wall_seconds.txt"
    mv "$dir.log" "$dir/log.txt"
  else
    printf '%s: %-18s reused  %s\n' "$scenario" "$label" "${dir#"$out"/}"
  fi
  printf '%s\t%s\t%s\n' "$label" "$dir" "$(cat "$dir/wall_seconds.txt" 2>/dev/null || echo nan)" \
    >> "$out/$scenario/runs.txt.part"
}

# study_figure: the scenario's figures, claims and summary from its runs (python/study/figure.py).
study_figure() {
  mv "$out/$scenario/runs.txt.part" "$out/$scenario/runs.txt"
  /usr/bin/python3 "$study_root/python/study/figure.py" "$scenario" "$study_dir" "$out/$scenario" \
    $([ $quick -eq 1 ] && echo --quick)
}

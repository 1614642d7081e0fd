#!/usr/bin/env bash
# Instruction counts of whole raylab processes under callgrind: the measure to
# develop performance work against on a shared machine, because it does not
# depend on the load (wall-clock times do). One thread, so the counts are
# repeatable run to run. Prints, per case, the process total, the inclusive
# counts of the phases (render(), scene loading, accelerator build, writeExr on
# the main thread) and the self counts by shared object (raylab, Embree, zlib,
# OpenEXR, libc, the dynamic loader, ...), in millions of instructions.
#
#   scripts/count-instructions.sh RAYLAB [CASE ...]      (default cases: balls tetra gears)
#
# CASE is one of the named cases below, or NAME='ARGS' for any `raylab render`
# arguments (the output and --threads 1 are added). Callgrind output is kept in
# ${WORK:-/tmp/raylab-counts}/NAME.cg for callgrind_annotate.
set -euo pipefail
bin=$(realpath "$1"); shift
top=$(cd "$(dirname "$0")/.." && pwd)
spd="$top/../shared/scenes/spd"
work=${WORK:-/tmp/raylab-counts}
mkdir -p "$work"
[[ $# -gt 0 ]] || set -- balls tetra gears

declare -A named=(
  [balls]="$spd/balls.nff --spd"
  [tetra]="$spd/tetra.nff --spd"
  [gears]="$spd/gears.nff --spd"
  [rings]="$spd/rings.nff --spd"
  [teapot]="$spd/teapot.nff --spd"
  [gears128]="$spd/gears.nff --spd --width 128 --height 128"
  [balls128]="$spd/balls.nff --spd --width 128 --height 128"
  [demo]="$top/scenes/demo.json --width 160 --height 120"
)

m() { awk -v x="${1//,/}" 'BEGIN { printf "%9.1f", x / 1e6 }'; }

printf '%-10s %9s %9s %9s %9s %9s | self by object\n' case total render parse build writeExr
for c in "$@"; do
  if [[ $c == *=* ]]; then name=${c%%=*}; args=${c#*=}; else name=$c; args=${named[$c]:?unknown case $c}; fi
  cg="$work/$name.cg"
  # shellcheck disable=SC2086
  valgrind --tool=callgrind --callgrind-out-file="$cg" "$bin" render $args \
      -o "$work/$name.exr" --quiet --threads 1 >"$work/$name.log" 2>&1 ||
    { echo "$name: raylab failed (see $work/$name.log)"; continue; }
  inc=$(callgrind_annotate --inclusive=yes --threshold=100 "$cg" 2>/dev/null)
  self=$(callgrind_annotate --threshold=100 "$cg" 2>/dev/null)
  pick() { grep -m1 -F "$1" <<<"$inc" | awk '{print $1}' || true; }
  total=$(grep -m1 'PROGRAM TOTALS' <<<"$inc" | awk '{print $1}')
  printf '%-10s %s %s %s %s %s | ' "$name" "$(m "$total")" "$(m "$(pick 'raylab::render(raylab::Scene const&')")" \
    "$(m "$(pick 'raylab::loadScene(')")" "$(m "$(pick 'raylab::makeAccelerator(')")" \
    "$(m "$(pick 'raylab::writeExr(')")"
  # Self counts summed per shared object (the [path] at the end of each line).
  awk '/^ *[0-9,]+ +\(/ && /\[/ {
         n = $1; gsub(",", "", n); obj = $NF; gsub(/^\[|\]$/, "", obj); sub(/.*\//, "", obj)
         sub(/\.so.*/, "", obj); sum[obj] += n }
       END { for (o in sum) if (sum[o] >= 1e6) printf "%s %.0f\n", o, sum[o] / 1e6 }' <<<"$self" |
    sort -k2 -nr | tr '\n' ' '
  echo
done

#!/usr/bin/env bash
# Renders every picture the project promises to keep with two raylab binaries
# and compares them: the RGBA layers with `raylab compare` (exit 0 only when
# bit-identical) and the whole EXR files byte for byte (AOV layers included);
# files whose bytes differ are "decoded-same" when every channel and header
# attribute is (idiff and exrheader, from the optional tools). A case whose
# bytes differ is rendered once more on both sides: "same-on-rerun" when the
# second pair is byte-identical, else the first pair's verdict stands. (A
# binary from before renderer/io/igzip_stream.h wrote another valid deflate
# stream in ~0.3% of processes: ISA-L 2.30 hashes the stream's address,
# docs/benchmarks.md, "igzip's output and the stream's address".)
# A developer's check before landing a change that must not change pictures.
#
#   scripts/picture-regression.sh OLD_RAYLAB NEW_RAYLAB [WORKDIR]
#
# Scenes: scenes/*.json, the bare OBJ meshes in scenes/meshes, and, when
# ../shared is present, every SPD scene (with and without --spd, Embree at
# full size and the naive loop at 96x96) and the shared OBJ models.
# Extra flags for every render can be given in RAYLAB_FLAGS (e.g. --threads 2),
# and flags for the new binary only in RAYLAB_NEW_FLAGS (e.g. a new flag that
# must reproduce the old pictures, such as --shadows opaque).
set -uo pipefail
old=$(realpath "$1"); new=$(realpath "$2")
top=$(cd "$(dirname "$0")/.." && pwd)
work=${3:-$(mktemp -d)}
mkdir -p "$work/old" "$work/new"
shared="$top/../shared"
flags=${RAYLAB_FLAGS:-}
newFlags=${RAYLAB_NEW_FLAGS:-}

cases=()   # "name|scene|flags"
for s in "$top"/scenes/*.json; do
  n=$(basename "$s" .json)
  cases+=("$n|$s|" "${n}_naive|$s|--accel naive --width 160 --height 120"
          "${n}_float|$s|--precision float" "${n}_eps|$s|--epsilon 1e-4 --robust --bvh-quality high")
done
for s in "$top"/scenes/meshes/*.obj; do
  n=$(basename "$s" .obj)
  cases+=("obj_$n|$s|--width 320 --height 240" "obj_${n}_naive|$s|--accel naive --width 96 --height 72")
done
if [[ -d "$shared/scenes/spd" ]]; then
  for s in "$shared"/scenes/spd/*.nff; do
    n=$(basename "$s" .nff)
    cases+=("spd_$n|$s|--spd" "nff_$n|$s|" "spd_${n}_naive|$s|--spd --accel naive --width 96 --height 96")
  done
  for n in gears teapot; do
    s="$shared/scenes/spd/$n.nff"
    [[ -f "$s" ]] || continue
    cases+=("nff_${n}_projected|$s|--polygons projected --width 256 --height 256"
            "nff_${n}_triangles|$s|--polygons triangles --width 256 --height 256"
            "nff_${n}_float|$s|--precision float --width 256 --height 256")
  done
fi
if [[ -d "$shared/models" ]]; then
  for s in "$shared"/models/*.obj "$shared"/models/spot/*.obj; do
    [[ -f "$s" ]] || continue
    n=$(basename "$s" .obj)
    cases+=("model_$n|$s|--width 320 --height 240")
  done
fi

# Files whose bytes differ may still hold the same image (another deflate
# stream, e.g. a change of compressor): every channel's values equal (idiff
# with no tolerance) and the same header attributes (exrheader's listing).
# Needs openimageio-tools and openexr (scripts/install-deps.sh --optional).
same_decoded() {
  command -v idiff >/dev/null && command -v exrheader >/dev/null || return 1
  idiff -q -fail 0 -warn 0 "$1" "$2" >/dev/null 2>&1 || return 1
  cmp -s <(exrheader "$1" | tail -n +3) <(exrheader "$2" | tail -n +3)
}

differ=0
printf '%-28s %-10s %-8s %s\n' case rgba exr-bytes flags
# render_both NAME SCENE EXTRA DIR: both binaries render the case into DIR/old and DIR/new.
render_both() {
  local name=$1 scene=$2 extra=$3 dir=$4 side bin sideFlags
  for side in old new; do
    bin=$old; sideFlags=
    [[ $side == new ]] && bin=$new && sideFlags=$newFlags
    mkdir -p "$dir/$side"
    # Same relative output name on both sides, so headers that record it match.
    (cd "$dir/$side" && "$bin" render "$scene" -o "$name.exr" --quiet $extra $flags $sideFlags \
        >"$name.log" 2>&1) || echo "render failed: $side $name (see $dir/$side/$name.log)"
    # A binary copied without raylab-openimageio.so beside it renders
    # textured scenes without their images: a difference that is not the code's.
    grep -q "OpenImageIO is not available" "$dir/$side/$name.log" &&
      echo "warning: $side binary has no raylab-openimageio.so beside it: $name rendered without its textures"
  done
}

for c in "${cases[@]}"; do
  IFS='|' read -r name scene extra <<<"$c"
  render_both "$name" "$scene" "$extra" "$work"
  if "$new" compare "$work/old/$name.exr" "$work/new/$name.exr" >"$work/new/$name.compare" 2>&1; then
    rgba=identical
  else
    rgba=DIFFERENT; differ=1
    # compare reads through raylab-openexr.so: without it every case "differs".
    grep -q "OpenEXR is not available" "$work/new/$name.compare" &&
      echo "warning: the new binary has no raylab-openexr.so beside it: $name not compared (see $work/new/$name.compare)"
  fi
  if cmp -s "$work/old/$name.exr" "$work/new/$name.exr"; then
    bytes=same
  else
    if same_decoded "$work/old/$name.exr" "$work/new/$name.exr"; then
      bytes=decoded-same
    else
      bytes=differ
    fi
    render_both "$name" "$scene" "$extra" "$work/rerun"
    cmp -s "$work/rerun/old/$name.exr" "$work/rerun/new/$name.exr" && bytes=same-on-rerun
  fi
  printf '%-28s %-10s %-8s %s\n' "$name" "$rgba" "$bytes" "$extra"
done
echo "renders and compare output in $work"
exit $differ

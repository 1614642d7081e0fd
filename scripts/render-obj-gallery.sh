#!/usr/bin/env bash
# Renders the OBJ gallery of docs/obj.md ("Gallery") into docs/img/obj/.
#
#   scripts/render-obj-gallery.sh [NEW_RAYLAB [OLD_RAYLAB]]
#
# NEW_RAYLAB defaults to build/bin/raylab; OLD_RAYLAB to the release before
# issue 17 (/work/baseline/raylab-3183e91), skipped with a note when absent.
# The models are written by scenes/obj_gallery/make_gallery.py into
# build/obj_gallery/ (not committed). Each model is rendered with the new
# binary (NAME.png) and, where the rule changed the picture, with the old one
# (NAME_before.png, or NAME_before.txt with its error when it refuses the file).
# The warnings each render prints go to build/obj_gallery/NAME.txt (and
# NAME_before.txt) for the docs to quote. Every picture is 256x192 at 4 samples
# per pixel (the wide bench 144x192); each command is the one docs/obj.md shows.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
new=$(realpath -m "${1:-$root/build/bin/raylab}")
old=$(realpath -m "${2:-/work/baseline/raylab-3183e91}")
# Relative paths from the repository root, so the warnings read as in docs/obj.md.
cd "$root"
models=build/obj_gallery
img=docs/img/obj
size=(--width 256 --height 192 --spp 4)

[ -x "$new" ] || { echo "render-obj-gallery: no raylab at $new (build it first)" >&2; exit 2; }
have_old=1
[ -x "$old" ] || { echo "render-obj-gallery: no old raylab at $old: 'before' pictures skipped" >&2; have_old=0; }

rm -rf "$models"
python3 scenes/obj_gallery/make_gallery.py "$models"
mkdir -p "$img"

# render BINARY SCENE PICTURE [flags...]: PNG, warnings in PICTURE's .txt (in $models).
render() {
    local bin=$1 scene=$2 name=$3
    shift 3
    local log=$models/$name.txt
    if "$bin" render "$models/$scene" -o "$models/$name.exr" --png "$img/$name.png" \
            "${size[@]}" --quiet "$@" 2>"$log"; then
        echo "  $name.png"
    else
        rm -f "$img/$name.png"
        echo "  $name: the render failed: $(cat "$log")"
    fi
}

# pair SCENE NAME [flags...]: the new binary, and the old one with the same flags.
pair() {
    local scene=$1 name=$2
    shift 2
    render "$new" "$scene" "$name" "$@"
    if [ "$have_old" = 1 ]; then render "$old" "$scene" "${name}_before" "$@"; fi
}

echo "render-obj-gallery: $new (and $old) into $img"
# Rules that changed pictures: the same JSON scene (camera, lights) for both.
pair faces.json faces
pair no_illum.json no_illum
pair no_ka.json no_ka
pair ns0.json ns0
pair names.json names
pair paths.json paths
pair smoothing.json smoothing
pair colours.json colours
# The first look of a bare OBJ: raylab frames and lights the model itself.
# The old binary has no --up or camera flags: it renders the bare file.
render "$new" house_zup.obj house_zup --up z
render "$new" house_zup.obj house_zup_default
if [ "$have_old" = 1 ]; then render "$old" house_zup.obj house_zup_before; fi
render "$new" tall.obj tall
if [ "$have_old" = 1 ]; then render "$old" tall.obj tall_before; fi
# A wide model in a portrait image: the limiting dimension is the width.
size=(--width 144 --height 192 --spp 4)
render "$new" bench.obj bench
if [ "$have_old" = 1 ]; then render "$old" bench.obj bench_before; fi
rm -f "$models"/*.exr
ls -l "$img"

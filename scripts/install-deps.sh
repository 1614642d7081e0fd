#!/usr/bin/env bash
# Installs the Debian 12 packages raylab needs, only those that are missing.
# Idempotent: a second run does nothing and needs no network. Uses sudo when
# not root. Usage: scripts/install-deps.sh [--optional]
#   --optional  also the tools for fuzzing, distributed rendering, the POV-Ray comparison and
#               the tests that open reports in a browser and rasterise plots
set -euo pipefail

required=(
  cmake make g++ pkg-config
  libembree-dev         # Embree 3: BVH build and traversal, user geometry
  libtbb-dev            # oneTBB: parallel tile loop
  libopenexr-dev        # OpenEXR: HDR output with AOV layers
  libisal-dev           # ISA-L's igzip: the deflate of the EXR's ZIP blocks (7x zlib's speed, same sizes) and of the PNG
  libtinyobjloader-dev  # tinyobjloader: MTL libraries; the reference OBJ parser of the differential test
  doctest-dev           # doctest: unit and render tests
  libpng-dev            # libpng: the tests decode the PNGs raylab writes with it
  python3               # scripts/spd (SPD generators, NFF -> POV-Ray) and their tests
  libopenimageio-dev    # OpenImageIO: texture images (PNG, JPEG, TGA, TIFF, BMP, HDR, EXR) and filtered lookups
)
optional=(
  clang libclang-rt-14-dev  # libFuzzer targets (make fuzz)
  libopenmpi-dev openmpi-bin # distributed rendering (-DRAYLAB_MPI=ON)
  povray                     # scripts/bench-povray.sh: raylab vs POV-Ray on the SPD scenes
  chromium                   # the headless-browser test of the HTML reports (--html)
  openimageio-tools openexr  # idiff, exrheader: scripts/picture-regression.sh compares decoded EXRs
  librsvg2-bin imagemagick libmagickcore-6.q16-6-extra fonts-dejavu-core
                             # the tests that rasterise a --plot SVG (rsvg-convert, convert)
)

wanted=("${required[@]}")
if [[ "${1:-}" == "--optional" ]]; then wanted+=("${optional[@]}"); fi

missing=()
for pkg in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

echo "raylab: installing missing packages: ${missing[*]}" >&2
sudo=()
if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2

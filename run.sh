#!/usr/bin/env bash
# grassfire: set up, build and run.
#   ./run.sh main   install what is missing, build, regenerate the figures and the
#                   proof-check report into paper-figures/out/ (open index.html)
#   ./run.sh test   install what is missing, build, run the whole test suite (CTest)
#   SANITIZE=1 ./run.sh test   the same with -fsanitize=address,undefined, in build-sanitize/
# Works on a fresh Debian bookworm machine as root (or with sudo).
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(cmake make g++ libcgal-dev libgmp-dev libmpfr-dev libboost-graph-dev catch2
          nlohmann-json3-dev librsvg2-bin libflint-arb-dev libpng-dev libgif-dev
          pybind11-dev python3-dev python3-numpy python3-venv python3-setuptools python3-wheel)
JOBS=${JOBS:-2}
SANITIZE=${SANITIZE:-0}
if [ "$SANITIZE" = 1 ]; then BUILD_DIR=${BUILD_DIR:-build-sanitize}; else BUILD_DIR=${BUILD_DIR:-build}; fi

install_missing() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "run.sh: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  local sanitize=OFF
  [ "$SANITIZE" = 1 ] && sanitize=ON
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DGF_SANITIZE=$sanitize
  if [ "$SANITIZE" = 1 ]; then
    # Only what CTest runs (no figures, no other studies): the sanitizer build is slow.
    cmake --build "$BUILD_DIR" -j"$JOBS" --target grassfire_tests fuzz_readers proof_checks \
          bench_complex_build bench_burn3d_exact
  else
    cmake --build "$BUILD_DIR" -j"$JOBS"
  fi
}

main_job() {
  local out=paper-figures/out
  mkdir -p "$out"
  "$BUILD_DIR"/proofs-checks/proof_checks --mutants --markdown "$out/proof-checks.md" --html "$out/proof-checks.html" \
    | tee "$out/proof-checks.txt"
  local checks=${PIPESTATUS[0]}
  "$BUILD_DIR"/paper-figures/paper_figures --out "$out"
  local n=0
  for svg in "$out"/*.svg; do
    [ -e "$svg" ] || continue
    rsvg-convert --width 1200 --keep-aspect-ratio --background-color white -o "${svg%.svg}.png" "$svg"
    n=$((n + 1))
  done
  echo "run.sh: $n figures in $out; open $out/index.html"
  [ "$checks" -eq 0 ] || { echo "run.sh: some proof checks failed (see $out/proof-checks.md)"; exit 1; }
}

case "${1:-}" in
  main) install_missing; build; main_job ;;
  test) install_missing; build; (cd "$BUILD_DIR" && ctest --output-on-failure -j"$JOBS") ;;
  *) sed -n '2,6p' "$0"; exit 2 ;;
esac

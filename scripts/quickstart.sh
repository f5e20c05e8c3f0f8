#!/usr/bin/env bash
# LtN quick start: install what is missing (Debian 12), build (Release), then
#   run   run the default scene and print where its output went, or
#   test  run the whole ctest suite.
#
# usage: bash scripts/quickstart.sh run|test
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$here/build"
jobs=$(nproc 2>/dev/null || echo 2)

# Debian 12 packages LtN builds and tests with. libopenblas0-pthread takes
# over the BLAS that deal.II's sparse direct solvers (MUMPS, UMFPACK) call:
# 4x faster factorizations in 3D than the reference BLAS.
packages=(cmake make g++ git libdeal.ii-dev libmumps-dev catch2 libeigen3-dev
          numdiff clang-format-16 python3 libopenblas0-pthread)

install_missing() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" ||
      missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return
  echo "Installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q \
    --no-install-recommends "${missing[@]}"
}

# build_ltn [TARGET]: the executable alone for `run`, everything for `test`.
build_ltn() {
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$build" -j "$jobs" ${1:+--target "$1"}
}

case "${1:-}" in
  run)
    install_missing
    build_ltn ltn
    cd "$here"
    "$build/ltn" parameter_files/lps_bar_3d_tensile_crack.prm
    ;;
  test)
    install_missing
    build_ltn
    cd "$build"
    # OpenMPI refuses to run as root without these; harmless otherwise.
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    ctest --output-on-failure -j "$jobs"
    ;;
  *)
    echo "usage: bash scripts/quickstart.sh run|test" >&2
    exit 2
    ;;
esac

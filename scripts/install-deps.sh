#!/usr/bin/env bash
# Installs the Debian 12 packages poresph needs. Idempotent: when every package is present it
# only checks (dpkg-query) and returns in well under a second.
#   scripts/install-deps.sh            solver, tests, VTK output (ParaView 5.11), the dashboard
#                                      (cpp-httplib; Chromium for its browser tests; Node.js and npm,
#                                      with which the front-end's npm packages install at build time)
#   scripts/install-deps.sh --minimal  solver and tests only (no ParaView; libtiff for TIFF images)
#   scripts/install-deps.sh --runtime  what a built poresph needs to run, with figures and reports
#                                      (no compilers, no -dev packages; the container images' last stage)
set -euo pipefail
mode=${1:-}

build=(build-essential cmake ninja-build libomp-dev
       libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
       libgtest-dev libbenchmark-dev libtiff-dev libhdf5-dev python3-h5py procps iproute2)
# (procps: the tests signal runs by name, pgrep and pkill; python3-h5py: they read checkpoints as users
# do; iproute2: a run over two hosts made of network namespaces)
# ParaView: its CMake package needs its Python modules and the -dev packages its exported
# targets name (MPI, GLEW, NetCDF, HDF5); OpenMPI (libopenmpi-dev, with mpirun) also runs one case
# over many processes, which write their checkpoints together through OpenMPI's parallel HDF5;
# Xvfb renders headless, ffmpeg assembles MP4s, matplotlib
# draws `poresph report`'s plots.
full=(paraview-dev python3-paraview libopenmpi-dev libhdf5-openmpi-dev libglew-dev libnetcdf-dev libx11-dev
      libfreetype-dev libboost-dev libxml2-dev xvfb ffmpeg libcpp-httplib-dev chromium python3-matplotlib)
# To run a built poresph: the libraries it links (ParaView's VTK comes with the paraview package;
# OpenMPI's library and mpirun, for runs over several processes), the pipelines' ParaView Python
# modules, Xvfb, ffmpeg, matplotlib.
runtime=(libgomp1 libtomlplusplus3 libtiff6 libcpp-httplib0.11 libopenmpi3 openmpi-bin libhdf5-openmpi-103-1 libhdf5-103-1
         paraview python3-paraview
         xvfb ffmpeg python3-matplotlib)
case $mode in
  --minimal) pkgs=("${build[@]}") ;;
  --runtime) pkgs=("${runtime[@]}") ;;
  "")
    pkgs=("${build[@]}" "${full[@]}")
    # The dashboard's front-end builds with Debian 12's own nodejs (18) and npm; a Node.js that is
    # already there (with its own npm, as NodeSource's) is kept: Debian's npm would clash with it.
    command -v node >/dev/null || pkgs+=(nodejs)
    command -v npm >/dev/null || pkgs+=(npm) ;;
  *) echo "install-deps: unknown option '$mode' (expected --minimal, --runtime or nothing)" >&2; exit 2 ;;
esac

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "poresph: installing ${missing[*]}" >&2
SUDO=""
[[ $(id -u) -eq 0 ]] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

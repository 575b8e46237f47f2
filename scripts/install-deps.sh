#!/usr/bin/env bash
# Installs gapfem's build and test dependencies from Debian 12 packages (idempotent: only what is
# missing is installed). Needs root (or sudo) when something is missing.
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config
          libeigen3-dev libsuitesparse-dev libmetis-dev libopenblas-dev
          libspectra-dev  # Spectra (on Eigen): the Lanczos method of *FREQUENCY
          petsc-dev  # PETSc (MUMPS, hypre, OpenMPI): --solver mumps|iterative, mpirun -np N
          slepc-dev  # SLEPc (on PETSc): *FREQUENCY and *BUCKLE on the PETSc backend, under mpirun
          libfmt-dev libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
          calculix-ccx python3 time
          gfortran  # gapfem --user compiles Abaqus UEL sources (and the tests' UEL)
          python3-vtk9  # tests read the ParaView frames back with VTK's own reader
          xvfb xauth libgl1-mesa-dri  # ... and render the README picture offscreen
          calculix-cgx  # a test reads job.frd with CalculiX's viewer in batch mode
          libjs-chart.js  # embedded into job.report.html by the build
          chromium  # a test renders job.report.html headless and checks the plots are drawn
          clang libclang-rt-14-dev llvm)  # clang: the sanitize build (ASan, UBSan, libFuzzer)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "gapfem: all dependencies are installed"
  exit 0
fi
echo "gapfem: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"

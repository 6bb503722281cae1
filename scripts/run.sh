#!/usr/bin/env bash
# splinex from zero: install what is missing (Debian 12, as root), configure, build, then run
#   scripts/run.sh test      the default test suite through ctest (what CI runs)
#   scripts/run.sh long [ctest flags]  the long label (hours: the full report, the proofs, the CLI
#                            fuzzer, the Slurm test), e.g. scripts/run.sh long -R slurm
#   scripts/run.sh report    the main job: build/bin/splinex report --out results (--bench bench/results)
#   scripts/run.sh sanitize  the ASan+UBSan build and its test run
#   scripts/run.sh fuzz [N]  the libFuzzer build (clang) and N executions (default 10^7)
#   scripts/run.sh bench     every benchmark, then the ratio tables bench/results/kernel.md (+ .json) and
#                            exactness.md (the report's "what exactness costs": splinex report --bench bench/results)
#   scripts/run.sh peers     SciPy's, Octave NURBS's and OpenCASCADE's results judged by splinex verify:
#                            results/peers/, then the report with them: results/report.md
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-test}
extra_packages=()
[[ $what == fuzz ]] && extra_packages=(clang libclang-rt-14-dev)
# The peers the kernel is benchmarked against (bench/bench_kernel.cpp): SISL and OpenCASCADE.
[[ $what == bench ]] && extra_packages=(libsisl-dev libocct-foundation-dev libocct-modeling-data-dev)
# The peers whose results `verify` judges (scripts/peers/): SciPy, the Octave NURBS toolbox, OpenCASCADE.
[[ $what == peers ]] && extra_packages=(python3-scipy octave-nurbs libocct-foundation-dev libocct-modeling-data-dev)
# The long label: a local Slurm and GNU parallel for the sweeps' test (tests/slurm/slurm_sweep.sh).
[[ $what == long ]] && extra_packages=(slurm-wlm munge parallel)

packages=(g++ cmake ninja-build pkg-config libgmp-dev libmpfr-dev libmpfi-dev libboost-dev libcgal-dev
          libflint-dev libeigen3-dev libcli11-dev nlohmann-json3-dev catch2 libbenchmark-dev python3
          python3-dev pybind11-dev python3-vtk9)
missing=()
for p in "${packages[@]}" "${extra_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "splinex: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  sudo=""; [[ $(id -u) != 0 ]] && sudo="sudo"
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

case "$what" in
  test)
    cmake --preset default >&2
    cmake --build --preset default
    ctest --preset default ;;
  long)
    cmake --preset default >&2
    cmake --build --preset default
    ctest --test-dir build -L long "${@:2}" ;;
  report)
    cmake --preset default >&2
    cmake --build --preset default --target splinex
    # What exactness costs: the committed tables of the last `scripts/run.sh bench` (dated inside).
    bench=(); [[ -f bench/results/exactness.md ]] && bench=(--bench bench/results)
    build/bin/splinex report --out results "${bench[@]}" ;;
  sanitize)
    cmake --preset sanitize >&2
    cmake --build --preset sanitize
    ctest --preset sanitize ;;
  fuzz)
    cmake --preset fuzz >&2
    cmake --build --preset fuzz --target fuzz_splinex
    fuzz/run_fuzz.sh build-fuzz/bin/fuzz_splinex tests/data build-fuzz/corpus "${2:-10000000}" ;;
  bench)
    cmake --preset default >&2
    cmake --build --preset default --target bench_kernel bench_compose bench_hybrid bench_vrep bench_solve bench_cut
    build/bin/bench_kernel --benchmark_out=build/bench_kernel.json --benchmark_out_format=json \
      "${@:2}" >&2
    mkdir -p build/bench_cases
    build/bin/bench_kernel --write-cases build/bench_cases
    python3 scripts/bench_python.py build/bench_cases build/bench_python.json
    # The higher levels (Algorithms 1 and 2 on the teapot, the hybrid patch) for the targets table.
    build/bin/bench_compose --benchmark_out=build/bench_compose.json --benchmark_out_format=json >&2
    build/bin/bench_hybrid --benchmark_out=build/bench_hybrid.json --benchmark_out_format=json >&2
    build/bin/bench_vrep --benchmark_out=build/bench_vrep.json --benchmark_out_format=json >&2
    build/bin/bench_solve --benchmark_out=build/bench_solve.json --benchmark_out_format=json >&2
    build/bin/bench_cut --benchmark_out=build/bench_cut.json --benchmark_out_format=json >&2
    python3 scripts/bench_table.py build/bench_kernel.json bench/results build/bench_python.json \
      --compose build/bench_compose.json --hybrid build/bench_hybrid.json --vrep build/bench_vrep.json \
      --solve build/bench_solve.json --cut build/bench_cut.json ;;
  peers)
    cmake --preset default >&2
    cmake --build --preset default --target splinex splinex_python occt_peer
    PYTHONPATH=build/python /usr/bin/python3 scripts/peers/judge_scipy.py results/peers "${2:-200}"
    PYTHONPATH=build/python /usr/bin/python3 scripts/peers/judge_octave.py results/peers "${2:-200}"
    PYTHONPATH=build/python /usr/bin/python3 scripts/peers/judge_occt.py results/peers "${2:-200}" build/bin/occt_peer
    build/bin/splinex report --out results --peers results/peers ;;
  *) echo "usage: scripts/run.sh [test|long [ctest flags]|report|sanitize|fuzz [N]|bench [benchmark flags]|peers [cases]]" >&2; exit 2 ;;
esac

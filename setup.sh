#!/usr/bin/env bash
# proxyvis setup: installs the Debian 12 dependencies, builds in Release and runs things.
#   ./setup.sh          install the dependencies only (idempotent; under a second when present)
#   ./setup.sh install-later
#                       install the packages test-long and test-sanitize add (Blender, Xvfb,
#                       clang 14); CI runs it in the background while the test command compiles
#   ./setup.sh build    install + configure + build everything (build/): programs, tests, benches
#   ./setup.sh demo     install + build + the main job on the bundled dragon-plane scene:
#                       proxy-gen -> proxy-check -> render-compare (MSE table + HTML report)
#   ./setup.sh test     install (with the npm packages of tests/js) + build the programs and
#                       tests (not the benches) + the correctness suite (ctest -LE long: every
#                       test but those labelled long)
#   ./setup.sh test-long
#                       install (with Blender and Xvfb) + build + only the tests labelled long:
#                       the local Slurm cluster (label slurm_cluster), headless Chromium (label
#                       browser) and the Blender add-on in a real Blender (label blender,
#                       docs/blender.md); they check orchestration and what a browser or Blender
#                       shows, not results the suite does not
#   ./setup.sh test --changed
#                       install + build + only the tests of the areas whose files changed since
#                       the last commit (PROXYVIS_CHANGED_BASE=REF: since REF); a quick check
#                       while working, never a substitute for the whole suite
#   ./setup.sh test-sanitize
#                       install + a second build tree (build-asan) with AddressSanitizer and
#                       UndefinedBehaviorSanitizer, then the whole test suite under them (long
#                       tests included, not_sanitized ones left out); it builds only what that
#                       suite runs (scripts/suite_targets.py)
#   ./setup.sh fuzz     install + clang-14 and libFuzzer, configure build-fuzz/ (ASan + UBSan +
#                       coverage) and build the fuzz targets of fuzz/ (run them: fuzz/run.sh)
#   ./setup.sh bench-deps
#                       install + what the benches need beyond the build: the npm packages of
#                       bench/vhacd_compare and python3-matplotlib (bench_break_even.py's plots)
# Each part of a command prints its wall and CPU time ("setup: build all: W s wall, C s CPU").
set -euo pipefail
cd "$(dirname "$0")"
BUILD_DIR=${PROXYVIS_BUILD_DIR:-build}
JOBS=${PROXYVIS_JOBS:-$(nproc)}
# ccache (the project's compiler launcher) in depend mode: on a miss it takes the headers from the
# compiler's own .d file instead of running the preprocessor once more. A fresh machine (CI) misses
# on every unit: that second preprocessing was 26 s of CPU over the Release build's 78 units and
# 18 s over the sanitizer build's 77. Hits are found as before.
export CCACHE_DEPEND=${CCACHE_DEPEND:-true}

# timed NAME COMMAND...: runs COMMAND, then prints "setup: NAME: W s wall, C s CPU" (C: the user
# + system time of the processes it ran). .ci/run's summary repeats these lines, so a CI log says
# where each step's time went (packages, npm, configure, compile, tests).
timed() {
  local name=$1 t0=$SECONDS c0
  shift
  children_cpu
  c0=$CHILDREN_CPU
  "$@"
  children_cpu
  echo "setup: $name: $((SECONDS - t0)) s wall, $(awk -v a="$c0" -v b="$CHILDREN_CPU" 'BEGIN { printf "%.0f", b - a }') s CPU"
}
# CHILDREN_CPU: the CPU seconds (user + system) of this shell's finished children, from the second
# line of `times`, which must run in this shell (in a $(...) subshell it reports the subshell's).
children_cpu() {
  local t
  t=$(mktemp)
  times >"$t"
  CHILDREN_CPU=$(awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, p, /[ms]/); s += p[1] * 60 + p[2] } print s }' "$t")
  rm -f "$t"
}

PKGS=(
  build-essential cmake ninja-build ccache pkg-config git python3
  lld  # the linker (CMakeLists.txt: 4-5x less link CPU than GNU ld)
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev
  libopenmesh-dev libembree-dev libdraco-dev
  libopenimageio-dev openimageio-tools libopencv-core-dev
  libopenexr-dev  # EXR files without loading OpenImageIO's ~250 libraries (lib/image/exr_io.h)
  libmeshoptimizer-dev libtbb-dev libtinygltf-dev
  libcli11-dev libfmt-dev nlohmann-json3-dev libssl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  chromium  # headless: the report test opens render-compare's HTML page in it
  slurm-wlm munge  # scripts/slurm: plans as job arrays; a single-node cluster for its tests
  openmpi-bin libopenmpi-dev  # data-parallel rendering (lib/distributed, mpirun)
  strace  # the data-parallel tests check which files each rank opens
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module (docs/python.md)
)

# Only for ./setup.sh fuzz and test-sanitize: clang with libFuzzer and the sanitizer runtimes.
FUZZ_PKGS=(clang-14 libclang-rt-14-dev)

# Only for ./setup.sh test-long: Blender 3.4 (Debian's runs on the system's Python 3.11, so the
# add-on imports NumPy and build/python/proxyvis) and a virtual X server for its panel's test
# (xvfb-run needs xauth). About 350 MB with their libraries: not in PKGS.
LONG_PKGS=(blender xvfb xauth)

install_deps() {
  install_pkgs "${PKGS[@]}"
}

install_pkgs() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all $# packages present"
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  # The package lists once an hour at most (CI's steps install three times in a few minutes).
  if ! find /var/lib/apt/lists -maxdepth 1 -name '*_InRelease' -mmin -60 2>/dev/null | grep -q .; then
    timed "apt-get update" $sudo apt-get update -qq
  fi
  # Another install running (CI installs the later steps' packages in the background) is waited
  # for, not an error.
  timed "apt-get install of ${#missing[@]} packages" $sudo apt-get install -y -qq \
    --no-install-recommends -o DPkg::Lock::Timeout=900 "${missing[@]}"
}

# The npm packages the tests run (tests/js/package-lock.json: the Khronos glTF-Validator and the
# glTF producers obj2gltf, gltf-pipeline, gltf-transform). Node.js comes from Debian (nodejs, npm)
# when the machine has none. Skipped when node_modules is newer than the lock file.
# npm_ci DIR: the exact packages of DIR/package-lock.json, unless they are already in place.
npm_ci() {
  command -v npm >/dev/null || install_pkgs nodejs npm
  local stamp="$1/node_modules/.package-lock.json"
  if [ -f "$stamp" ] && [ "$stamp" -nt "$1/package-lock.json" ]; then
    return
  fi
  echo "setup: npm ci in $1"
  timed "npm ci in $1" env -C "$1" npm ci --no-audit --no-fund --loglevel=error
}

install_js_deps() { npm_ci tests/js; }

# The same in the background, so that the download overlaps the build (18 s of wall time here,
# 10 s of CPU); wait_js_deps waits for it (and fails if it failed) before the tests start.
start_js_deps() {
  command -v npm >/dev/null || install_pkgs nodejs npm
  npm_ci tests/js &
  JS_DEPS_PID=$!
}
wait_js_deps() { wait "$JS_DEPS_PID"; }

# build [TARGET...]: configure, then build the targets given (default: the programs and the
# tests; the target `benches` adds bench/). The demo builds only the programs it runs.
build() {
  timed configure cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
  local targets=()
  [ $# -eq 0 ] || targets=(--target "$@")
  timed "build ${*:-all}" cmake --build "$BUILD_DIR" -j "$JOBS" "${targets[@]}"
}

# The sanitizer build: clang 14 (the fuzz build's compiler, so a second compiler checks the code
# too): unit by unit it compiled this tree under ASan + UBSan in 20.8 min of two cores, where
# GCC 12 needs about 28 by the per-unit ratios (the heaviest CGAL unit 158 s against 200 s, a
# JSON-heavy test 18 s against 29 s). -O1 -g1 (line tables: readable stacks at tolerable speed; -O2 was
# tried with GCC: the suite ran at most 8 % faster, the build took twice as long), NDEBUG like
# Release so the same code is tested, benches off. Any UBSan finding aborts (no recovery), so a
# test with one fails; ASan leak checking is on. Suppressions of third-party findings live in
# .ci/. PROXYVIS_ASAN_CXX=g++ PROXYVIS_ASAN_CC=gcc builds it with GCC instead.
sanitize_env() {
  local supp="$PWD/.ci"
  export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:detect_stack_use_after_return=0:check_initialization_order=1:suppressions=$supp/asan.supp"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp"
  export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
  # ASan replaces malloc, so render-compare's re-start with glibc's huge-page malloc would only
  # double every start (1.5 s each here: the sanitizer build loads OpenImageIO at start).
  export GLIBC_TUNABLES=glibc.malloc.hugetlb=0
}

build_sanitize() {
  local dir=${PROXYVIS_ASAN_BUILD_DIR:-build-asan}
  local cxx=${PROXYVIS_ASAN_CXX:-clang++-14} cc=${PROXYVIS_ASAN_CC:-clang-14}
  local flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
  # GCC's -Wmaybe-uninitialized gives false positives on sanitizer-instrumented code (seen in
  # OpenMesh's Property.hh); the Release build keeps the warning. Clang has no such option.
  local warn="-Wno-maybe-uninitialized"
  case "$cxx" in *clang*) warn="" ;; esac
  # A tree configured with the other compiler starts afresh (CMake cannot switch compilers).
  if [ -f "$dir/CMakeCache.txt" ] && ! grep -q "^CMAKE_CXX_COMPILER:[A-Z]*=.*/$cxx\$" "$dir/CMakeCache.txt"; then
    echo "setup: $dir was configured with another compiler: removing it"
    rm -rf "$dir"
  fi
  sanitize_env  # the options the tests run under
  timed configure cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_C_COMPILER="$cc" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS="$flags $warn" -DCMAKE_C_FLAGS="$flags $warn" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" \
    -DCMAKE_MODULE_LINKER_FLAGS="$flags" \
    -DPROXYVIS_BUILD_BENCH=OFF -DPROXYVIS_PRELOAD_OIIO_MODULE=ON -DPROXYVIS_TESTS_PER_EXECUTABLE=ON
  # Only what the suite below runs: the default build less the test executables whose every
  # ctest entry is left out (scripts/suite_targets.py; today proxy_tight_tests).
  local list targets
  list=$(python3 scripts/suite_targets.py "$dir" -LE not_sanitized)
  mapfile -t targets <<<"$list"
  timed "build of ${#targets[@]} targets" cmake --build "$dir" -j "$JOBS" --target "${targets[@]}"
  # Tests labelled not_sanitized are too slow under ASan (see their definition for why). One job
  # per core: with one more (as the Release suite runs) a CPU-bound app test with a time limit
  # (proxy_gen_budget.erode_non_manifold_fin_is_general, 75 s of its 120) timed out.
  timed ctest ctest --test-dir "$dir" --output-on-failure -j "$JOBS" -LE not_sanitized
}

# The fuzz build: clang, every library instrumented, no tests/benches, mesh-info (fuzz/run.sh
# encodes its Draco seeds with it) and every fuzz/fuzz_*.cpp target.
fuzz_build() {
  local dir=${PROXYVIS_FUZZ_BUILD_DIR:-build-fuzz}
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 -DPROXYVIS_FUZZ=ON \
    -DPROXYVIS_BUILD_TESTS=OFF -DPROXYVIS_BUILD_BENCH=OFF -DPROXYVIS_BUILD_APPS=ON
  local targets=(mesh-info)
  for f in fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
  cmake --build "$dir" -j "$JOBS" --target "${targets[@]}"
}

# The ctest label expression for `test --changed`: tests/<area> mirrors lib/<area>, so a file
# under lib/<area>/ or tests/<area>/ selects <area>; proxies/ selects proxies, apps/ the programs'
# tests and the bad-input corpus, lib/distributed its MPI jobs too. What everything depends on
# (lib/util, the build files, data, scenes) selects every test.
changed_labels() {
  local base=${PROXYVIS_CHANGED_BASE:-HEAD} files f area labels=()
  files=$( (git diff --name-only "$base"; git ls-files --others --exclude-standard) | sort -u)
  [ -n "$files" ] || { echo "none"; return; }
  for f in $files; do
    case "$f" in
      lib/util/* | CMakeLists.txt | */CMakeLists.txt | *.cmake | setup.sh | data/* | scenes/*)
        echo "all"; return ;;
      lib/distributed/*) labels+=(distributed mpi); continue ;;
      lib/plan/* | lib/study/*) labels+=(plan study apps bad_inputs slurm); continue ;;
      lib/* | tests/*) area=${f#*/}; area=${area%%/*} ;;
      proxies/*) area=proxies ;;
      apps/python/*) labels+=(python); continue ;;
      apps/*) labels+=(apps bad_inputs); continue ;;
      docs/* | README.md) area=docs ;;
      *) continue ;;
    esac
    labels+=("$area")
  done
  [ ${#labels[@]} -gt 0 ] || { echo "none"; return; }
  printf '%s\n' "${labels[@]}" | sort -u | sed 's/.*/^&$/' | paste -sd'|'
}

# The tests labelled long (local Slurm cluster, headless Chromium, Blender) run only with
# test-long.
# The suite runs one test more than there are cores: its tests wait now and then (process
# starts, MPI ranks waiting for each other, deliberate sleeps), and the extra one keeps the
# cores busy meanwhile (2 cores, same tree: 243 s at -j3 against 257 s at -j2, CPU time equal).
run_tests() {
  local CTEST_JOBS=${PROXYVIS_TEST_JOBS:-$((JOBS + 1))}
  if [ "${1:-}" = "--changed" ]; then
    local expr
    expr=$(changed_labels)
    case "$expr" in
      none) echo "setup: no changed file selects a test area"; return ;;
      all) echo "setup: a change everything depends on: the whole suite" ;;
      *) echo "setup: the tests labelled $expr"
         ctest_run -L "$expr" -LE long
         return ;;
    esac
  elif [ -n "${1:-}" ]; then
    echo "usage: $0 test [--changed]" >&2
    exit 2
  fi
  ctest_run -LE long
}

# ctest on the build tree (ctest starts the tests that took longest in earlier runs first).
ctest_run() {
  timed ctest ctest --test-dir "$BUILD_DIR" --output-on-failure -j "${CTEST_JOBS:-$JOBS}" "$@"
}

demo() {
  local bin="$BUILD_DIR/bin" out=out/dragon-plane
  mkdir -p "$out"
  echo "== 1/3 proxy-gen: outside proxies for every mesh of scenes/dragon-plane.json"
  "$bin/proxy-gen" scenes/dragon-plane.json --kind outside --out-dir "$out/proxies" --json "$out/proxy-gen.json"
  echo "== 2/3 proxy-check: classify every proxy with sampled rays + exact containment"
  "$bin/proxy-check" "$out/proxies/scene.json" --rays 200000 --json "$out/proxy-check.json"
  echo "== 3/3 render-compare: every estimator against a converged reference"
  "$bin/render-compare" "$out/proxies/scene.json" --out "$out/report" ${PROXYVIS_DEMO_FLAGS:-}
}

case "${1:-install}" in
  install) install_deps ;;
  install-later) install_pkgs "${LONG_PKGS[@]}" "${FUZZ_PKGS[@]}" ;;
  build) install_deps; build all benches ;;
  demo) install_deps; build proxy-gen proxy-check render-compare; demo ;;
  test) install_deps; start_js_deps; build; wait_js_deps; run_tests "${2:-}" ;;
  test-long) install_deps; install_pkgs "${LONG_PKGS[@]}"; install_js_deps; build; ctest_run -L long ;;
  fuzz) install_deps; install_pkgs "${FUZZ_PKGS[@]}"; fuzz_build ;;
  test-sanitize) install_deps; install_pkgs "${FUZZ_PKGS[@]}"; install_js_deps; build_sanitize ;;
  bench-deps) install_deps; install_pkgs python3-matplotlib; npm_ci bench/vhacd_compare ;;
  *) echo "usage: $0 [install|install-later|build|demo|test|test-long|test-sanitize|fuzz|bench-deps]" >&2; exit 2 ;;
esac

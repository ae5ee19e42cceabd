#!/usr/bin/env bash
# One entry point for people and CI.
#   scripts/dev.sh run    install what is missing, build, convert the bundled corpus/ into out/corpus
#   scripts/dev.sh test   install what is missing, build, run every test (unit, harness, lit, corpus),
#                         then the sanitizer tree: unit, lit and corpus tests under ASan + UBSan, each
#                         fuzz target for a fixed number of inputs (STEREOSHIFT_FUZZ_SECONDS=N: N seconds) and the fuzz regressions
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
mode="${1:-run}"

# Debian packages the build and the tests need (see README "Dependencies").
packages=(cmake ninja-build g++ python3 glslang-dev glslang-tools spirv-tools
          libspirv-cross-c-shared-dev spirv-cross libcli11-dev llvm-14-tools
          mesa-vulkan-drivers libvulkan-dev nlohmann-json3-dev libxxhash-dev libtomlplusplus-dev
          googletest libgtest-dev
          # Mesa's OpenGL driver, loaded at run time (transpiler/frontend/mesa_compiler.h): a real
          # GLSL compiler's word before a route says yes to a shader glslang refuses.
          libegl1 libegl-mesa0 libgl1-mesa-dri)
# Test mode only: clang and its runtimes for the sanitizer tree (ASan, UBSan, libFuzzer), and piglit,
# whose shader_runner runs the GL-side execution tests in Mesa's OpenGL driver (execution.piglit).
if [ "$mode" = test ]; then packages+=(clang-14 libclang-rt-14-dev piglit); fi
# Bazel and nginx (integration.bazel_example and integration.bazel_remote_cache, which serves Bazel's
# --remote_cache from nginx's WebDAV module, are skipped without them): opt-in, because their install
# (a JDK) and their tests add about a minute to a suite that CI runs within its time on two cores.
if [ "$mode" = test ] && [ -n "${STEREOSHIFT_WITH_BAZEL:-}" ]; then packages+=(bazel-bootstrap nginx); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=""; [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}"
fi

# Optimised, with line tables only (-g1): backtraces and sanitizer reports keep file:line, and GCC
# compiles the tree's files 25-40% faster than with full debug information (-g); CI pays that on
# every run.
build_type=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
build_dir="${STEREOSHIFT_BUILD_DIR:-build}"
cmake -S . -B "$build_dir" -G Ninja "${build_type[@]}" >/dev/null
case "$mode" in
  run)
    # Only the tool: the corpus job needs nothing else (tests and benchmarks build in `test` mode).
    cmake --build "$build_dir" --parallel "$(nproc)" --target stereoshift
    "$build_dir/stereoshift" build corpus -o out/corpus
    ;;
  test)
    cmake --build "$build_dir" --parallel "$(nproc)"
    ctest --test-dir "$build_dir" --output-on-failure --parallel "$(nproc)"

    # The same tool under AddressSanitizer + UndefinedBehaviorSanitizer (cmake/Sanitizers.cmake), in a
    # tree of its own; only what its tests need (no execution harness, no benchmarks).
    sanitize_dir="${STEREOSHIFT_SANITIZE_BUILD_DIR:-build-sanitize}"
    cmake -S . -B "$sanitize_dir" -G Ninja "${build_type[@]}" -DBUILD_TESTING=ON \
          -DCMAKE_CXX_COMPILER=clang++-14 -DSTEREOSHIFT_SANITIZE=ON >/dev/null
    cmake --build "$sanitize_dir" --parallel "$(nproc)" --target stereoshift_sanitizer_suite
    ctest --test-dir "$sanitize_dir" --output-on-failure --parallel "$(nproc)" \
          -R '^(unit|unit[.].*|lit|corpus|fuzz[.]regressions[.].*)$'
    # Each fuzz target from the seeds (corpus/, the lit tests) for a fixed number of inputs with a fixed
    # libFuzzer seed, so a busy machine finds what an idle one finds (STEREOSHIFT_FUZZ_RUNS_SCALE scales
    # the budgets); STEREOSHIFT_FUZZ_SECONDS=N explores for N seconds per target from the corpus that
    # earlier runs in this tree grew instead. A crash in our code fails either way.
    if [ -n "${STEREOSHIFT_FUZZ_SECONDS:-}" ]; then
      fuzz_budget=(--seconds "$STEREOSHIFT_FUZZ_SECONDS")
    else
      fuzz_budget=(--runs --runs-scale "${STEREOSHIFT_FUZZ_RUNS_SCALE:-1}")
    fi
    python3 test/fuzz/run_fuzz.py fuzz --bin-dir "$sanitize_dir/test/fuzz" --seeds "$sanitize_dir/test/fuzz/seeds" \
            --work "$sanitize_dir/test/fuzz/work" "${fuzz_budget[@]}"
    ;;
  *)
    echo "usage: scripts/dev.sh [run|test]" >&2; exit 2 ;;
esac

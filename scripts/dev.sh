#!/usr/bin/env bash
# One entry point for people and CI.
#   scripts/dev.sh run    install what is missing, build, convert the bundled corpus/ into out/corpus
#   scripts/dev.sh test   install what is missing, build, run every test (unit, harness, lit, corpus)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
mode="${1:-run}"

# Debian packages the build and the tests need (see README "Dependencies").
packages=(cmake ninja-build g++ python3 glslang-dev glslang-tools spirv-tools
          libspirv-cross-c-shared-dev spirv-cross libcli11-dev llvm-14-tools
          mesa-vulkan-drivers libvulkan-dev nlohmann-json3-dev libxxhash-dev libtomlplusplus-dev
          googletest libgtest-dev)
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

build_dir="${STEREOSHIFT_BUILD_DIR:-build}"
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"

case "$mode" in
  run)
    "$build_dir/stereoshift" build corpus -o out/corpus
    ;;
  test)
    ctest --test-dir "$build_dir" --output-on-failure --parallel "$(nproc)"
    ;;
  *)
    echo "usage: scripts/dev.sh [run|test]" >&2; exit 2 ;;
esac

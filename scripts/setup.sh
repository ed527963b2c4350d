#!/usr/bin/env bash
# The first set-up command of README.md: install the Debian packages dayphoton needs, build it
# (Release, into build/), and run the main job on the example project projects/office.
# Safe to run again: packages already present are not reinstalled, the build is incremental.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake make g++ pkg-config
  libembree-dev libgeographiclib-dev libopenexr-dev libyaml-cpp-dev nlohmann-json3-dev
  libtbb-dev libcli11-dev libgtest-dev libpng-dev zlib1g-dev
  libpugixml-dev  # BSDF XML files (docs/architecture.md)
  openmpi-bin libopenmpi-dev  # runs over MPI ranks (dist/, docs/cluster.md); the build also works without
  python3
  clang libfuzzer-14-dev  # the fuzz harnesses (scripts/fuzz.sh, docs/fuzzing.md)
  chromium  # headless browser of the report test (tests/report/)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"

# The main job on the example project: the whole daylight study of the reference office
# (results in projects/office/results/, see docs/outputs.md).
./build/app/dayphoton run projects/office/project.yaml

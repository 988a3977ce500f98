#!/usr/bin/env bash
# Installs the Debian 12 packages kutlog needs to build, test, benchmark and draw. Idempotent:
# quiet and quick when everything is already there. Run as root.
#   --aarch64: also the arm64 libraries the aarch64 cross build links (scripts/test-aarch64.sh),
#              after enabling Debian's arm64 architecture (multiarch) if it is not.
set -euo pipefail

packages=(
  build-essential cmake python3 universal-ctags
  libxsimd-dev libgtest-dev libbenchmark-dev libopenimageio-dev libmpfr-dev libcli11-dev
  libfmt-dev nlohmann-json3-dev
  fonts-dejavu-core python3-matplotlib
  clang-14 libclang-rt-14-dev
  g++-aarch64-linux-gnu qemu-user  # the aarch64 cross build, run under qemu-aarch64
)
if [ "${1:-}" = --aarch64 ]; then
  dpkg --print-foreign-architectures | grep -qx arm64 || dpkg --add-architecture arm64
  packages+=(libc6:arm64 libxsimd-dev:arm64 libgtest-dev:arm64 libmpfr-dev:arm64 libfmt-dev:arm64)
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

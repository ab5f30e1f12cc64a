#!/usr/bin/env bash
# Installs every Debian 12 package facet needs. Idempotent; run as root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  glslang-dev glslang-tools spirv-tools spirv-cross libspirv-cross-c-shared-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  libglm-dev libopenimageio-dev libpng-dev openimageio-tools nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev libxxhash-dev libzstd-dev
  libtbb-dev libtinyobjloader-dev libtinygltf-dev clang-14 libclang-rt-14-dev libcurl4-openssl-dev libssl-dev glslc
  chromium
  python3-jsonschema libxml2-utils  # facetc --check's report tests validate SARIF and JUnit with them
  nginx  # the remote-cache tests run it as a WebDAV server (its dav module is built in)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"

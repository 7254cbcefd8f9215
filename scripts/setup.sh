#!/usr/bin/env bash
# Installs everything Penumbra needs to build and test, from Debian 12 packages only.
# Idempotent and non-interactive: packages already present are left alone.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libvulkan-dev glslc spirv-tools
  mesa-vulkan-drivers vulkan-validationlayers   # lavapipe (CPU Vulkan) + validation for tests
  vulkan-validationlayers-dev                   # vk_enum_string_helper.h (string_VkResult)
  libstb-dev libtinyexr-dev libcli11-dev
  libopenexr-dev libxxhash-dev                  # EXR (any compression: --aov, env maps, textures), checkpoint keys
  libtiff-dev                                   # TIFF textures and environment maps
  libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev zlib1g-dev   # zlib: .ply.gz
  libassimp-dev                                 # FBX, Collada, 3DS, STL, ... (src/scene/io/assimp_loader.cpp)
  libgtest-dev libbenchmark-dev
  libtbb-dev                                    # the top-level BVH rebuild on a worker pool (src/bvh/morton_build.cpp)
  libglfw3-dev libimgui-dev xvfb xauth         # the viewer (penumbra view) and its test under Xvfb
  libopenmpi-dev openmpi-bin                    # render across ranks under mpirun (docs/DISTRIBUTED.md)
  clang libclang-rt-14-dev                      # libFuzzer targets (tests/fuzz)
  freedoom glmark2-data assimp-testmodels       # real scenes the tests load (never committed)
  libturbojpeg0-dev libboost-dev                # penumbra serve: JPEG frames, HTTP + WebSocket (Boost.Beast)
  libavcodec-dev libavformat-dev libswscale-dev # H.264 videos of walks and sequences (src/image/video_writer.cpp)
  chromium firefox-esr                          # the browser tests of penumbra serve (tests/browser)
  ccache                                        # compiler cache for CI's two builds (.ci/run)
)

# The browser tests' drivers (tests/browser: playwright-core for Chromium, puppeteer-core for
# Firefox; pinned in its package-lock.json).
# Node 20 or later is needed; Debian 12's own nodejs is 18, so a newer one must already be there.
install_browser_test_driver() {
  local dir
  dir="$(cd "$(dirname "$0")/.." && pwd)/tests/browser"
  command -v npm >/dev/null || { echo "setup: npm not found: the browser tests will not run" >&2; return 0; }
  [ -d "$dir/node_modules/playwright-core" ] && [ -d "$dir/node_modules/puppeteer-core" ] || npm ci --prefix "$dir" --no-audit --no-fund >/dev/null
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  install_browser_test_driver
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
install_browser_test_driver

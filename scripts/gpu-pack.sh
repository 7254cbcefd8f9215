#!/usr/bin/env bash
# scripts/gpu-pack.sh BINARY [EXTRA_FILE...]
# (The project's own packer, kept here so a plain clone can pack; it was ../shared/tools/gpu-pack.sh.)
# Packs a program built on this machine so that it runs on the lent GPU machine, which has the
# NVIDIA driver but no Vulkan loader, no package registry and none of our libraries.
# Creates ./.gpu/ in the current git checkout (and ignores it in .git/info/exclude):
#   .gpu/bin/      the program(s) and any extra files named
#   .gpu/lib/      every shared library they load, except glibc's own
#   .gpu/debs/     the Vulkan/GL loader packages (libvulkan1, libglvnd...) unpacked there at run time
#   .gpu/env.sh    source it first on the GPU machine: unpacks the loaders, sets LD_LIBRARY_PATH
# On the GPU machine (device tool `run`, with carry [".gpu"]):
#   source .gpu/env.sh && .gpu/bin/penumbra info
# FFmpeg's libraries load about 110 others (x265, AV1, codec2, TLS, ICU data...), 140 MB as they
# are; by default only what an H.264 encode/decode in mp4/mkv runs stays real (see
# scripts/gpu_stub_libs.py --ffmpeg-minimal) and the rest become stubs:
#   GPU_PACK_VIDEO_MINIMAL=0   carry FFmpeg's whole closure, real (every codec and protocol works)
#   GPU_PACK_NO_VIDEO=1        no video at all: FFmpeg itself becomes empty stubs (benchmark packs)
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 BINARY [EXTRA_FILE...]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
top=$(git rev-parse --show-toplevel)
cd "$top"
grep -qx '/.gpu/' .git/info/exclude 2>/dev/null || { mkdir -p .git/info; echo '/.gpu/' >> .git/info/exclude; }
rm -rf .gpu/bin .gpu/lib
mkdir -p .gpu/bin .gpu/lib .gpu/debs
for f in "$@"; do cp -L "$f" .gpu/bin/; done
# shared libraries, minus glibc (the GPU machine's own, newer, is used)
for f in .gpu/bin/*; do
  case "$(file -bL "$f")" in ELF*) ;; *) continue ;; esac
  ldd "$f" | awk '/=> \//{print $3}' | while read -r lib; do
    case "$(basename "$lib")" in
      libc.so*|libm.so*|libpthread.so*|libdl.so*|librt.so*|ld-linux*|libresolv.so*) ;;
      *) cp -Ln "$lib" .gpu/lib/ ;;
    esac
  done
done
# GPU_PACK_NO_VIDEO=1: for benchmark packs that never write a video. FFmpeg's libraries and
# everything only they load (x265, AV1, codec2, ICU data...) are about 45 MB compressed, too much
# to travel beside the WebGPU peer; FFmpeg's own libraries become stubs (gpu_stub_libs.py: the
# same names and symbol versions, functions that return zero) and what only they loaded is
# dropped, so penumbra starts and only writing a video fails.
if [ "${GPU_PACK_NO_VIDEO:-0}" = 1 ]; then
  python3 "$here/gpu_stub_libs.py" .gpu $(cd .gpu/lib && ls libavcodec.so.* libavformat.so.* libavutil.so.* \
                                                   libswscale.so.* libswresample.so.* 2>/dev/null)
elif [ "${GPU_PACK_VIDEO_MINIMAL:-1}" != 0 ]; then
  # Videos are written and read with libx264 and FFmpeg's own H.264 decoder in mp4/mkv; the
  # codecs, protocols and hardware front ends FFmpeg links besides become stubs of the same names
  # (it binds them at load, BIND_NOW, so they must be there), which shrinks the pack by 140 MB.
  python3 "$here/gpu_stub_libs.py" --ffmpeg-minimal .gpu
fi
if ! ls .gpu/debs/libvulkan1_*.deb >/dev/null 2>&1; then
  lists=/tmp/gpu-pack-apt-lists; mkdir -p "$lists/partial"
  o="-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=$lists"
  apt-get $o update >/dev/null
  (cd .gpu/debs && apt-get $o download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null 2>&1)
fi
cat > .gpu/env.sh <<'ENV'
# source me on the GPU machine
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
for f in "$here"/debs/*.deb; do dpkg -x "$f" / ; done
ldconfig
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ] && [ ! -f /usr/share/vulkan/icd.d/nvidia_icd.json ]; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
export PATH="$here/bin:$PATH"
ENV
du -sh .gpu | awk '{print "packed .gpu/: " $1 " (the device tool carries at most 64 MiB in all)"}'

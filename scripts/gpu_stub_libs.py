#!/usr/bin/env python3
"""Replaces packed shared libraries that a GPU-host run never calls with small stubs.

    scripts/gpu_stub_libs.py PACK_DIR LIB_NAME...          stub the named libraries
    scripts/gpu_stub_libs.py --ffmpeg-minimal PACK_DIR     stub every library that only FFmpeg needs

PACK_DIR is gpu-pack.sh's .gpu/ (bin/ and lib/). Each stubbed library in PACK_DIR/lib becomes a
stub of the same soname that defines exactly the symbols (with their versions) the other packed
files import from it: functions that return zero, data of the right size (zeros). FFmpeg's
libraries are linked with BIND_NOW, so every import must resolve at load even for codecs nobody
opens; the stubs satisfy that without the codecs (x265, AV1, codec2, SVG, ICU's data...), which
are most of the pack's size. The stub functions return zero (a null pointer, a zero version),
since codec registration asks some of them for versions and capabilities even for codecs nobody
opens. Then libraries that nothing packed needs any more are deleted.

--ffmpeg-minimal computes the list instead of taking one. It keeps real what an H.264 encode or
decode in mp4/mkv runs (libavcodec, libavformat, libavutil, libswscale, libswresample, libx264,
and libgme, whose demuxer probe runs on every input opened); every library a packed program needs
other than through FFmpeg (the Vulkan loader, assimp, OpenEXR, Open MPI...); and every library a
Vulkan driver or layer installed here loads directly (libdrm: a stub would be loaded in its
place). It stubs the rest of FFmpeg's closure: the other codecs, the network and TLS libraries,
hardware-acceleration front ends (VA-API, VDPAU, OpenCL), SVG and font rendering. Any other
codec, protocol or filter then fails at its first call (a null handle or a crash).

Imports are matched with care: a versioned import only to that version, an unversioned one only
where no kept library or glibc defines the name too (a stub must never shadow a real function),
and weak imports not at all (their users check for them).
"""
import argparse
import os
import re
import subprocess
import tempfile

# FFmpeg's own libraries: their dependencies are FFmpeg's closure (followed only for FFmpeg).
FFMPEG_PREFIXES = ("libavcodec.so", "libavformat.so", "libavutil.so", "libavfilter.so", "libavdevice.so",
                   "libswscale.so", "libswresample.so", "libpostproc.so")
# What a libx264 encode and a native H.264 decode in mp4/mkv load and call: kept real. Also libgme:
# opening any input probes every demuxer, and the libgme demuxer's probe dereferences what
# gme_identify_header returns (a stub's null pointer crashes the decode).
FFMPEG_MINIMAL_KEEP = ("libavcodec.so", "libavformat.so", "libavutil.so", "libswscale.so", "libswresample.so",
                       "libx264.so", "libgme.so")
# Where the Vulkan loader finds the drivers and layers it loads at run time.
VULKAN_MANIFEST_DIRS = [os.path.join(root, "vulkan", kind) for root in ("/usr/share", "/etc")
                        for kind in ("icd.d", "implicit_layer.d", "explicit_layer.d")]
# glibc: the host's own is used, never packed; its symbols are never stubbed.
GLIBC = ("libc.so.6", "libm.so.6", "libdl.so.2", "libpthread.so.0", "librt.so.1", "libresolv.so.2")


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def elf_files(pack):
    for folder in ("bin", "lib"):
        d = os.path.join(pack, folder)
        for name in sorted(os.listdir(d)):
            path = os.path.join(d, name)
            with open(path, "rb") as f:
                if f.read(4) == b"\x7fELF":
                    yield path


def needed(path):
    return re.findall(r"Shared library: \[(.*?)\]", run("readelf", "-d", path))


def symbols(path, defined):
    """name@version (or name) -> (type letter, size) of the dynamic symbols defined or imported."""
    flag = "--defined-only" if defined else "--undefined-only"
    out = {}
    for line in run("nm", "-D", "-S", flag, "--with-symbol-versions", path).splitlines():
        parts = line.split()
        if defined and len(parts) >= 4:
            size, kind, name = int(parts[1], 16), parts[2], parts[3]
        elif defined and len(parts) == 3:
            size, kind, name = 0, parts[1], parts[2]
        elif not defined and len(parts) >= 2:
            size, kind, name = 0, parts[-2], parts[-1]
        else:
            continue
        out[name] = (kind, size)
    return out


def imports(paths):
    """(plain name, version or '') of every strong import of the given files. Weak imports are left
    out: code that references a symbol weakly checks for it, and a missing one is safer there than
    a stub that returns zero."""
    out = set()
    for path in paths:
        for full, (kind, _) in symbols(path, False).items():
            if kind not in "wv":
                plain, _, version = full.partition("@")
                out.add((plain, version.lstrip("@")))
    return out


def defined_names(paths):
    """Plain names of the dynamic symbols the given files define."""
    return {full.split("@")[0] for path in paths for full, (kind, _) in symbols(path, True).items() if kind != "A"}


def glibc_paths():
    """This machine's glibc libraries (their symbols win over any stub's for unversioned imports)."""
    out = []
    for line in run("ldconfig", "-p").splitlines():
        name, _, path = line.strip().partition(" => ")
        if name.split(" ")[0] in GLIBC and "x86-64" in name and path not in out:
            out.append(path)
    return out


def stub(pack, lib, wanted_imports, defined_elsewhere):
    """Rewrites PACK/lib/LIB as a stub defining what the kept files import from it. An import with a
    version binds only to that version; an unversioned one is left to a kept library or glibc that
    also defines the name, so that a stub never shadows a real function."""
    path = os.path.join(pack, "lib", lib)
    by_plain = {}
    for full, info in symbols(path, True).items():
        plain, _, version = full.partition("@")
        if info[0] != "A":
            by_plain[plain] = (version.lstrip("@"), info)
    wanted = {}
    for plain, version in wanted_imports:
        if plain not in by_plain:
            continue
        if version and version != by_plain[plain][0]:
            continue
        if not version and plain in defined_elsewhere:
            continue
        wanted[plain] = by_plain[plain]
    versions, source = {}, ["#include <stddef.h>"]
    for plain, (version, (kind, size)) in sorted(wanted.items()):
        versions.setdefault(version, []).append(plain)
        if kind in "TtWiI":
            source.append(f"long {plain}(void) {{ return 0; }}")
        else:
            source.append(f"char {plain}[{max(size, 1)}];")
    soname = re.search(r"Library soname: \[(.*?)\]", run("readelf", "-d", path))
    with tempfile.TemporaryDirectory() as tmp:
        c, vmap = os.path.join(tmp, "stub.c"), os.path.join(tmp, "stub.map")
        with open(c, "w") as f:
            f.write("\n".join(source) + "\nvoid penumbra_pack_stub(void) {}\n")
        with open(vmap, "w") as f:
            unversioned = versions.pop("", [])
            f.write("{ global: penumbra_pack_stub; %s local: *; };\n" % "".join(s + "; " for s in unversioned)
                    if not versions else "")
            for i, (version, names) in enumerate(sorted(versions.items())):
                extra = "penumbra_pack_stub; " + "".join(s + "; " for s in unversioned) if i == 0 else ""
                f.write("%s { global: %s%s local: *; };\n" % (version, extra, "".join(s + "; " for s in names)))
        run("cc", "-shared", "-fPIC", "-fno-builtin", "-w", "-o", path, "-Wl,-soname," + (soname.group(1) if soname else lib),
            "-Wl,--version-script=" + vmap, c)
    return len(wanted)


def reachable(pack, follow, extra_roots=()):
    """Packed libraries the programs in PACK/bin (and the packed libraries extra_roots) need,
    directly or through a library for which follow(name) is true."""
    libs = set(os.listdir(os.path.join(pack, "lib")))
    reach = set(extra_roots)
    todo = [p for p in elf_files(pack) if "/bin/" in p] + [os.path.join(pack, "lib", n) for n in extra_roots]
    while todo:
        for name in needed(todo.pop()):
            if name in libs and name not in reach:
                reach.add(name)
                if follow(name):
                    todo.append(os.path.join(pack, "lib", name))
    return reach


def prune(pack):
    """Deletes libraries that no packed program needs, directly or through another library."""
    libs = set(os.listdir(os.path.join(pack, "lib")))
    gone = libs - reachable(pack, lambda name: True)
    for name in gone:
        os.remove(os.path.join(pack, "lib", name))
    return sorted(gone)


def vulkan_driver_needs():
    """What the Vulkan drivers and layers installed here need directly (libdrm, libxcb...). A stub
    carries the real library's soname, so a driver loaded later would get the stub in its place:
    those stay real. (Lavapipe runs the suite here; the GPU host's NVIDIA driver needs X11 alone.)"""
    out = set()
    for folder in VULKAN_MANIFEST_DIRS:
        if not os.path.isdir(folder):
            continue
        for manifest in sorted(os.listdir(folder)):
            with open(os.path.join(folder, manifest), errors="replace") as f:
                lib = re.search(r'"library_path"\s*:\s*"([^"]*)"', f.read())
            if lib:
                path = lib.group(1) if lib.group(1).startswith("/") else os.path.join(folder, lib.group(1))
                if os.path.exists(path):
                    out.update(needed(path))
    return out


def ffmpeg_only(pack):
    """Packed libraries that only FFmpeg's closure needs, minus what an H.264 encode/decode runs:
    every library not reachable from the programs or the Vulkan drivers without passing through
    FFmpeg's own libraries."""
    libs = set(os.listdir(os.path.join(pack, "lib")))
    not_ffmpeg = lambda name: not name.startswith(FFMPEG_PREFIXES)
    elsewhere = reachable(pack, not_ffmpeg, sorted(vulkan_driver_needs() & libs))
    return sorted(n for n in libs - elsewhere if not n.startswith(FFMPEG_MINIMAL_KEEP))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ffmpeg-minimal", action="store_true",
                        help="stub every library only FFmpeg needs, beside those an H.264 encode/decode runs")
    parser.add_argument("pack", metavar="PACK_DIR")
    parser.add_argument("libs", metavar="LIB_NAME", nargs="*")
    args = parser.parse_args()
    pack = args.pack
    names = list(args.libs) + (ffmpeg_only(pack) if args.ffmpeg_minimal else [])
    present = sorted({n for n in names if os.path.exists(os.path.join(pack, "lib", n))})
    # Stub first (each stub drops its own imports), then prune what only the stubbed needed.
    kept = [p for p in elf_files(pack) if os.path.basename(p) not in present]
    wanted = imports(kept)
    elsewhere = defined_names(kept + glibc_paths())
    total = 0
    for lib in present:
        total += stub(pack, lib, wanted, elsewhere)
    print(f"gpu_stub_libs: {len(present)} libraries -> stubs of {total} symbols in all: " + " ".join(present))
    removed = prune(pack)
    if removed:
        print("gpu_stub_libs: no longer needed: " + " ".join(removed))


if __name__ == "__main__":
    main()

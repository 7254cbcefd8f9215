#!/usr/bin/env python3
"""Replaces packed shared libraries that a GPU-host run never calls with small stubs.

    scripts/gpu_stub_libs.py PACK_DIR LIB_NAME...

PACK_DIR is gpu-pack.sh's .gpu/ (bin/ and lib/). Each named library in PACK_DIR/lib becomes a stub
of the same soname that defines exactly the symbols (with their versions) the other packed files
import from it: functions that return zero, data of the right size (zeros). FFmpeg's libraries are
linked with BIND_NOW, so every import must resolve at load even for codecs nobody opens; the stubs
satisfy that without the codecs (x265, AV1, codec2, SVG, ICU's data...), which are most of the
pack's size. The stub functions return zero (a null pointer, a zero version), since codec
registration asks some of them for versions and capabilities even for codecs nobody opens. Then libraries that nothing packed needs any more are deleted.
"""
import os
import re
import subprocess
import sys
import tempfile


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


def stub(pack, lib, importers):
    path = os.path.join(pack, "lib", lib)
    defined = symbols(path, True)
    by_plain = {}
    for full, info in defined.items():
        plain, _, version = full.partition("@")
        by_plain[plain] = (version.lstrip("@"), info)
    wanted = {}
    for other in importers:
        for full in symbols(other, False):
            plain = full.split("@")[0]
            if plain in by_plain:
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


def prune(pack):
    """Deletes libraries that no packed program needs, directly or through another library."""
    libs = {name for name in os.listdir(os.path.join(pack, "lib"))}
    reach, todo = set(), [p for p in elf_files(pack) if "/bin/" in p]
    while todo:
        for name in needed(todo.pop()):
            if name in libs and name not in reach:
                reach.add(name)
                todo.append(os.path.join(pack, "lib", name))
    for name in libs - reach:
        os.remove(os.path.join(pack, "lib", name))
    return sorted(libs - reach)


def main():
    pack, names = sys.argv[1], sys.argv[2:]
    present = [n for n in names if os.path.exists(os.path.join(pack, "lib", n))]
    # Stub first (each stub drops its own imports), then prune what only the stubbed needed.
    importers = [p for p in elf_files(pack) if os.path.basename(p) not in present]
    for lib in present:
        count = stub(pack, lib, importers)
        print(f"gpu_stub_libs: {lib} -> stub of {count} symbols")
    removed = prune(pack)
    if removed:
        print("gpu_stub_libs: no longer needed: " + " ".join(removed))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Builds stand-in shared libraries for a portable bundle of the testbed.

Usage: gpu_stubs.py OUT_DIR KEPT_ELF... -- STUBBED_LIB...

Each STUBBED_LIB (a real library path) gets a stand-in OUT_DIR/<its soname> that defines
exactly the symbols the KEPT_ELF files import from it, with the same symbol versions, and
needs nothing itself. A function stand-in prints which library was called and aborts (a constructor
or destructor returns: kept libraries build static objects of those types at load; a
version query returns "": OpenImageIO lists every format's library version); an
object stand-in is zeros of the real size. The dynamic loader is satisfied (Debian builds
OpenImageIO with BIND_NOW, so every import must resolve at start), while the libraries'
own dependency trees (OSMesa's LLVM, OpenImageIO's OpenCV, FFmpeg and OpenVDB: some
500 MB) stay behind. Only code paths the GPU bundle never takes (the osmesa backend, the
viewer, exotic image formats) reach a stand-in.
"""
import os
import re
import subprocess
import sys
import tempfile

SYMBOL = re.compile(r"^\s*\d+:\s+[0-9a-f]+\s+(\d+|0x[0-9a-f]+)\s+(\w+)\s+(\w+)\s+\w+\s+(\w+)\s+(\S+)")


def dyn_symbols(path):
    """(name, version or None, default?, type, size, defined?) of every dynamic symbol."""
    out = subprocess.run(["readelf", "--dyn-syms", "-W", path], capture_output=True, text=True,
                         check=True).stdout
    for line in out.splitlines():
        m = SYMBOL.match(line)
        if not m or m.group(3) == "LOCAL":
            continue
        size, kind, _, ndx, full = m.groups()
        name, version, default = full, None, True
        if "@@" in full:
            name, version = full.split("@@", 1)
        elif "@" in full:
            name, version = full.split("@", 1)
            default = False
        yield name, version, default, kind, int(size, 0), ndx != "UND"


def is_structor(symbols):
    """Which mangled names are constructors or destructors (`A::B::B(...)`, `A::B::~B()`)."""
    out = subprocess.run(["c++filt"], input="\n".join(symbols), capture_output=True, text=True,
                         check=True).stdout.splitlines()
    result = {}
    for mangled, plain in zip(symbols, out):
        parts = plain.split("(", 1)[0].split("::")
        result[mangled] = len(parts) >= 2 and parts[-1].lstrip("~") == parts[-2].split("<")[0]
    return result


def soname(path):
    out = subprocess.run(["readelf", "-d", path], capture_output=True, text=True, check=True).stdout
    m = re.search(r"\(SONAME\).*\[(.*)\]", out)
    return m.group(1) if m else os.path.basename(path)


def needed_versions(kept, file_name):
    """Version names that the kept files require from the library called file_name."""
    names = set()
    for path in kept:
        out = subprocess.run(["readelf", "-V", "-W", path], capture_output=True, text=True).stdout
        current = None
        for line in out.splitlines():
            m = re.search(r"File: (\S+)", line)
            if m:
                current = m.group(1)
                continue
            m = re.search(r"Name: (\S+)", line)
            if m and current == file_name:
                names.add(m.group(1))
    return names


def build_stub(lib, kept, imports, out_dir):
    name = soname(lib)
    wanted = {}
    for sym, version, default, kind, size, defined in dyn_symbols(lib):
        if defined and (sym, version) in imports or (defined and (sym, None) in imports and default):
            wanted[(sym, version)] = (kind, size, default)
    versions = needed_versions(kept, name) | {v for (_, v) in wanted if v}
    message = f"testbed bundle: stand-in {name} was called"
    asm = [".text", "stub_die:", "  lea stub_message(%rip), %rsi", "  mov $2, %edi",
           f"  mov ${len(message) + 1}, %edx", "  call write@PLT", "  call abort@PLT",
           "stub_empty: lea stub_zeros(%rip), %rax", "  ret",
           ".section .rodata", f'stub_message: .ascii "{message}\\n"', ".balign 16",
           "stub_zeros: .zero 64"]
    structors = is_structor([sym for sym, _ in wanted])
    unversioned = []
    for i, ((sym, version), (kind, size, default)) in enumerate(sorted(wanted.items(), key=str)):
        local = f"stub_{i}"
        if kind in ("FUNC", "IFUNC", "NOTYPE"):
            # Static objects of the stood-in library's types are built and destroyed in the
            # kept libraries' initializers (OpenImageIO registers with DCMTK at load): let them.
            # A version query answers "" (OpenImageIO asks every format's library once).
            body = "ret" if structors[sym] else "jmp stub_empty" if "version" in sym.lower() else "jmp stub_die"
            asm += [".text", f"{local}: {body}"]
        elif kind == "TLS":
            asm += ['.section .tbss,"awT",@nobits', f"{local}: .zero {max(size, 8)}"]
        else:
            asm += [".data", ".balign 16", f"{local}: .zero {max(size, 8)}"]
        typ = {"FUNC": "@function", "IFUNC": "@function", "TLS": "@tls_object"}.get(kind, "@object")
        asm += [f".globl {local}", f".type {local}, {typ}", f".size {local}, {max(size, 8)}"]
        if version:
            asm.append(f'.symver {local}, "{sym}@{"@" if default else ""}{version}"')
        else:
            asm += [f'.globl "{sym}"', f'.set "{sym}", {local}']
            unversioned.append(sym)
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "stub.s"), "w") as f:
            f.write("\n".join(asm) + "\n")
        with open(os.path.join(tmp, "stub.map"), "w") as f:
            # Every version the kept files require exists; the stand-ins' own labels stay local.
            nodes = sorted(versions)
            exported = "global: " + " ".join(f'"{s}";' for s in unversioned) if unversioned else ""
            if not nodes:
                f.write(f"{{ {exported} local: *; }};\n")
            for k, v in enumerate(nodes):
                f.write(f"{v} {{ {exported if k == 0 else ''} local: stub_*; }};\n")
        subprocess.run(["gcc", "-shared", "-nostartfiles", "-o", os.path.join(out_dir, name),
                        f"-Wl,-soname,{name}", f"-Wl,--version-script,{tmp}/stub.map",
                        os.path.join(tmp, "stub.s")], check=True)
    return name, len(wanted)


def main():
    args = sys.argv[1:]
    if "--" not in args or len(args) < 4:
        sys.exit(__doc__)
    split = args.index("--")
    out_dir, kept, stubbed = args[0], args[1:split], args[split + 1:]
    imports = set()
    for path in kept:
        for sym, version, _, _, _, defined in dyn_symbols(path):
            if not defined:
                imports.add((sym, version))
    os.makedirs(out_dir, exist_ok=True)
    for lib in stubbed:
        name, count = build_stub(lib, kept, imports, out_dir)
        print(f"stand-in {name}: {count} symbols", file=sys.stderr)


if __name__ == "__main__":
    main()

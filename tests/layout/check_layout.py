#!/usr/bin/env python3
"""The tree shows its libraries: every #include between the source folders follows the layout
table of docs/design.md ("Layout"), and no two folders include each other, directly or through
others. Exits 1 naming the file, line and include that breaks it.

Usage: check_layout.py SOURCE_DIR
"""
import os
import re
import sys

# folder -> the folders its files may include (besides its own). Deeper folders are listed
# separately: sky/night may not include sky/ (the SkyState that is built from it).
ALLOWED = {
    "protocol": set(),
    "ephemeris": set(),
    "shaders": set(),
    "calibration": {"sky"},
    "sky/common": set(),
    "sky/atmosphere": {"shaders"},
    "sky/analytic": {"sky/common", "shaders"},
    "sky/eye": {"shaders"},
    "sky/night": {"sky/atmosphere", "sky/common", "ephemeris", "shaders"},
    "sky/nvis": {"sky/night", "sky/atmosphere", "sky/common", "ephemeris", "shaders"},
    "sky": {"sky/atmosphere", "sky/common", "sky/analytic", "sky/eye", "sky/night", "sky/nvis", "ephemeris", "shaders"},
    "render/gl": {"shaders"},
    "render/passes": {"calibration", "render/gl", "sky", "sky/atmosphere", "sky/eye", "sky/night", "sky/common", "ephemeris", "shaders"},
    "render": {"calibration", "render/gl", "render/passes", "sky", "sky/atmosphere", "sky/eye", "sky/night", "sky/analytic", "sky/common",
               "ephemeris", "shaders"},
    # The public library: the node's services (its sky worker, configuration, data loading) and
    # the renderer behind the headers of api/include/skyig.
    "api": {"services", "render", "render/gl", "render/passes", "sky", "sky/atmosphere", "sky/common", "sky/analytic",
            "sky/eye", "sky/night", "ephemeris", "shaders", "calibration", "protocol"},
}
# services/ is the node: it may include every library but the public one (api/), which is built
# on it; the commands (services/commands) may include everything, and nothing includes them.
TOP = ["protocol", "ephemeris", "calibration", "shaders", "sky", "render", "services", "api"]
EVERYTHING_BUT = {"services": {"api", "services/commands"}, "services/commands": set()}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_of(path):
    """The layout folder of a file path relative to the source root (deepest listed folder)."""
    parts = path.split("/")
    for depth in (2, 1):
        f = "/".join(parts[:depth])
        if len(parts) > depth and (f in ALLOWED or f in EVERYTHING_BUT):
            return f
    return None


def resolve(root, including_file, name):
    for base in (root, os.path.join(root, "shaders"), os.path.dirname(including_file)):
        p = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(p):
            return os.path.relpath(p, root)
    return None


def main(root):
    errors, edges = [], {}
    for top in TOP:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for f in files:
                if not f.endswith((".h", ".cpp", ".glsl", ".frag", ".vert", ".comp")):
                    continue
                path = os.path.join(dirpath, f)
                rel = os.path.relpath(path, root)
                src = folder_of(rel)
                with open(path, encoding="utf-8") as fh:
                    for n, line in enumerate(fh, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = resolve(root, path, m.group(1))
                        dst = folder_of(target) if target else None
                        if dst is None or dst == src:
                            continue
                        edges.setdefault(src, set()).add(dst)
                        if src in EVERYTHING_BUT:
                            if dst in EVERYTHING_BUT[src]:
                                errors.append(f"{rel}:{n}: includes {m.group(1)}: {src}/ may not depend on {dst}/")
                        elif dst == "services/commands" or (dst == "services" and "services" not in ALLOWED[src]):
                            errors.append(f"{rel}:{n}: includes {m.group(1)}: only the public library and the commands may include {dst}/")
                        elif dst not in ALLOWED[src]:
                            errors.append(f"{rel}:{n}: includes {m.group(1)}: {src}/ may not depend on {dst}/")
    # A loop between folders (also one the table would allow by mistake).
    def visit(node, stack):
        for nxt in sorted(edges.get(node, ())):
            if nxt in stack:
                errors.append("folder loop: " + " -> ".join(stack[stack.index(nxt):] + [nxt]))
                continue
            visit(nxt, stack + [nxt])
    for node in sorted(edges):
        visit(node, [node])
    for e in sorted(set(errors)):
        print(e)
    if errors:
        return 1
    print("layout: %d folders, %d dependencies, no loop" % (len(edges), sum(len(v) for v in edges.values())))
    for src in sorted(edges):
        print("  %-15s -> %s" % (src, ", ".join(sorted(edges[src]))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))

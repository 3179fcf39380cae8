#!/usr/bin/env python3
"""The tree shows its libraries: every #include between the source folders follows the layout
table of docs/design.md ("Layout"), no two folders include each other directly or through
others, and the layers keep their purity: no GL in the physics, the sky state, the protocol, the
ephemeris or the calibration; no socket outside the node's transport and the commands; none
reached by the public API's headers. Exits 1 naming the file, line and include that breaks it.

An include is resolved as the compilers resolve it: from the source root (C++ and GLSL alike),
from the public headers (api/include), then beside the including file.

Usage: check_layout.py SOURCE_DIR
"""
import os
import re
import sys

# folder -> the folders its files may include (besides its own). A folder is the deepest one
# listed here that holds the file.
PHYSICS_COMMON = {"physics/common"}
ALLOWED = {
    "protocol": set(),
    "ephemeris": set(),
    "physics/common": set(),
    "physics/spectrum": set(),
    "physics/display": PHYSICS_COMMON,
    "physics/analytic": PHYSICS_COMMON,
    "physics/atmosphere": PHYSICS_COMMON | {"physics/spectrum"},
    "physics/eye": PHYSICS_COMMON | {"physics/display"},
    "physics/night": PHYSICS_COMMON | {"physics/atmosphere", "physics/spectrum", "ephemeris"},
    "physics/moon": PHYSICS_COMMON | {"physics/night", "physics/atmosphere", "physics/spectrum", "ephemeris"},
    "physics/stars": PHYSICS_COMMON | {"physics/night", "physics/eye", "physics/atmosphere", "physics/spectrum",
                                       "ephemeris"},
    "physics/goggle": PHYSICS_COMMON | {"physics/night", "physics/moon", "physics/stars", "physics/atmosphere",
                                        "physics/spectrum", "ephemeris"},
    "physics/weather": PHYSICS_COMMON,
    "physics": {"physics/common", "physics/analytic", "physics/eye", "physics/display"},
    "sky": {"physics", "physics/common", "physics/spectrum", "physics/display", "physics/analytic",
            "physics/atmosphere", "physics/eye", "physics/night", "physics/moon", "physics/stars", "physics/goggle",
            "physics/weather", "ephemeris"},
    "calibration": {"sky", "physics/common"},
}
# Each group below may include everything listed above it (and in ALLOWED), in this order, and
# its own earlier members; nothing above may include it.
LOWER = set(ALLOWED)
ORDERED = [
    ("render/glsl", set()),
    ("render/gl", {"render/glsl"}),
    ("render/passes/common", {"render/gl", "render/glsl"}),
    ("render/passes/precompute", {"render/gl", "render/glsl", "render/passes/common"}),
    ("render/passes/tone", {"render/gl", "render/glsl", "render/passes/common"}),
    ("render/passes/night", {"render/gl", "render/glsl", "render/passes/common", "render/passes/tone"}),
    ("render/passes/sky", {"render/gl", "render/glsl", "render/passes/common", "render/passes/tone",
                           "render/passes/night"}),
    ("render/passes/goggle", {"render/gl", "render/glsl", "render/passes/common"}),
    ("render/passes/projector", {"render/gl", "render/glsl", "render/passes/common"}),
    ("render", {"render/gl", "render/glsl", "render/passes/common", "render/passes/precompute", "render/passes/tone",
                "render/passes/sky", "render/passes/night", "render/passes/goggle", "render/passes/projector"}),
    ("render/client", {"render", "render/gl", "render/glsl", "render/passes/common", "render/passes/sky",
                       "render/passes/tone"}),
    ("tables", {"render/passes/precompute", "render/gl"}),
    ("node/common", set()),
    ("node/host", {"node/common"}),
    ("node/transport", {"node/common", "node/host"}),
    ("node/config", {"node/common", "node/host", "node/transport", "tables", "render", "render/gl",
                     "render/passes/projector"}),
    ("node/frame", {"node/common", "node/host", "node/config", "tables", "render", "render/gl", "render/client",
                    "render/passes/goggle", "render/passes/projector", "render/passes/tone", "render/passes/sky"}),
    ("node/record", {"node/common", "node/host", "node/transport", "node/config", "node/frame", "tables", "render",
                     "render/gl"}),
    ("node", {"node/common", "node/host", "node/transport", "node/config", "node/frame", "node/record", "tables",
              "render", "render/gl"}),
]
# The public library may include every library but the commands; the commands everything.
TOP_ANY = {"api": {"commands"}, "commands": set()}
GL = re.compile(r'^\s*#\s*include\s+[<"](glad/|GL/|EGL/|GLFW/|render/)')
SOCKET = re.compile(r'^\s*#\s*include\s+<(sys/socket\.h|netinet/|arpa/inet\.h|netdb\.h|linux/can|net/if\.h)')
NO_GL = ("protocol", "ephemeris", "physics", "sky", "calibration")
# The host's state and the frames are pure (node/host/sender.h stands for the kernel's address).
SOCKETS_ALLOWED = ("node/transport", "node/common", "node/config", "node/record", "node/node.", "commands", "tests")
SOURCES = (".h", ".cpp", ".glsl", ".frag", ".vert", ".comp")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
# One definition of the units, with no dependency of its own: every folder may include it.
UNITS = "physics/common/units.h"
TOP = ["protocol", "ephemeris", "physics", "sky", "calibration", "render", "tables", "node", "api", "commands"]

for name, below in ORDERED:
    ALLOWED[name] = LOWER | below
KNOWN = set(ALLOWED) | set(TOP_ANY)


def folder_of(path):
    """The layout folder of a file path relative to the source root (deepest listed folder)."""
    parts = path.split("/")
    for depth in range(len(parts) - 1, 0, -1):
        f = "/".join(parts[:depth])
        if f in KNOWN:
            return f
    return None


def resolve(root, including_file, name):
    for base in (root, os.path.join(root, "api", "include"), os.path.dirname(including_file)):
        p = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(p):
            return os.path.relpath(p, root)
    return None


def check_file(root, path, rel, src, edges, errors):
    with open(path, encoding="utf-8") as fh:
        lines = fh.readlines()
    for n, line in enumerate(lines, 1):
        if GL.match(line) and rel.startswith(NO_GL):
            errors.append(f"{rel}:{n}: {line.strip()}: no GL below the renderer")
        if SOCKET.match(line) and not rel.startswith(SOCKETS_ALLOWED):
            errors.append(f"{rel}:{n}: {line.strip()}: socket headers only in the node\'s transport, config, record and common parts and the commands")
        m = INCLUDE.match(line)
        if not m:
            continue
        target = resolve(root, path, m.group(1))
        dst = folder_of(target) if target else None
        if dst is None or dst == src or target == UNITS:
            continue
        edges.setdefault(src, set()).add(dst)
        if src in TOP_ANY:
            if dst in TOP_ANY[src]:
                errors.append(f"{rel}:{n}: includes {m.group(1)}: {src}/ may not depend on {dst}/")
        elif dst in TOP_ANY:
            errors.append(f"{rel}:{n}: includes {m.group(1)}: only the commands may include {dst}/")
        elif dst not in ALLOWED.get(src, set()):
            errors.append(f"{rel}:{n}: includes {m.group(1)}: {src}/ may not depend on {dst}/")


def api_reaches_sockets(root):
    """The public library's files and what they include, transitively: none may name a socket header."""
    errors, seen = [], set()
    todo = [os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(os.path.join(root, "api"))
            for f in fs if f.endswith(SOURCES)]
    while todo:
        rel = todo.pop()
        if rel in seen:
            continue
        seen.add(rel)
        with open(os.path.join(root, rel), encoding="utf-8") as fh:
            for n, line in enumerate(fh, 1):
                if SOCKET.match(line):
                    errors.append(f"{rel}:{n}: {line.strip()}: the public API reaches a socket header")
                m = INCLUDE.match(line)
                if m:
                    t = resolve(root, os.path.join(root, rel), m.group(1))
                    if t:
                        todo.append(t)
    return errors


def main(root):
    errors, edges = [], {}
    for top in TOP:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for f in files:
                if not f.endswith(SOURCES):
                    continue
                path = os.path.join(dirpath, f)
                rel = os.path.relpath(path, root)
                src = folder_of(rel)
                if src is None:
                    errors.append(f"{rel}: in no folder of the layout table")
                    continue
                check_file(root, path, rel, src, edges, errors)
    if os.path.isdir(os.path.join(root, "api", "include")):
        errors += api_reaches_sockets(root)

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
        print("  %-24s -> %s" % (src, ", ".join(sorted(edges[src]))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))

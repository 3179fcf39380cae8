#!/usr/bin/env python3
"""Writes the small MPCDI and Bourke fixtures of tests/calibration (Python's standard library
only; run it from anywhere, it writes beside itself). Each fixture encodes ONE known warp, the
function uv() below, which tests/calibration/mpcdi_test.cpp evaluates too:

  warp_absolute.mpcdi   profile 3d, zip, PFM values are the absolute image coordinates uv()
  warp_offset/          profile 3d, a folder, PFM values are uv() minus the node's grid place
  points_a3.mpcdi       profile a3, zip, PFM values are 3D points on a 3 m sphere in the
                        direction the 3d fixtures' camera shows at uv(), in a surveyor's axes
                        (x right, y forward, z up) around an eye at EYE
  mesh_bourke.txt       a Bourke warp mesh of the same uv() (v up), intensity = ALPHA()

All: region "p1", a 64 x 40 projector, a 9 x 6 warp grid, alpha and beta maps 16 x 10.

The same warp again in the conventions of VESA's reference library (the MPCDI SDK of Scalable
Display Technologies, v1.0; read, not copied: its writer src/IO/mpcdiWriterIntern.cpp and its
PFM writer src/IO/mpcdiPfmIO.cpp), as its ExampleCreateProfileTypes programs write each profile:
root attributes profile, date, level, version "1.0"; Xresolution and Yresolution on the buffer
and the region; the frustum's children in the order yaw, pitch, roll, rightAngle, leftAngle,
upAngle, downAngle; the files at the zip's root as GeometryWarpFile-<region>.pfm,
AlphaMap-<region>.png, BetaMap-<region>.png; the warp's geometricUnit, interpolation and
originof3DData (which the SDK fills with the interpolation's word); the PFM header "PF", the
sizes, "-1.000000" (little-endian), rows bottom-up:

  sdk_2d.mpcdi          profile 2d, region r1, no frustum, the warp's uv()
  sdk_3d.mpcdi          profile 3d, region r1 with FRUSTUM; an RGB alpha map (componentDepth 3)
                        whose green and blue are 0.8 and 0.6 of its red (in light)
  sdk_a3.mpcdi          profile a3, region r1 with a coordinate frame and NO frustum (the SDK's
                        a3 example has none), points_a3's points; gammaEmbedded 0 (the SDK's
                        value when it was never set)
  sdk_sl.mpcdi          profile sl, region r1 with FRUSTUM, points 3 m from the origin
  sdk_sl_three.mpcdi    profile sl, regions r1, r2, r3 with FRUSTUM turned to yaw -40, 10, 60
"""
import math
import os
import struct
import zipfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
W, H = 64, 40            # the projector
GW, GH = 9, 6            # the warp grid
BW, BH = 16, 10          # the blend maps
GAMMA_EMBEDDED = 2.2
FRUSTUM = dict(yaw=10.0, pitch=-5.0, roll=2.0, leftAngle=-30.0, rightAngle=25.0, downAngle=-15.0, upAngle=20.0)
EYE = (0.1, 0.2, -0.05)  # surveyor axes: right, forward, up (metres)


def uv(s, t):
    """The warp: grid place (s, t) in [0, 1] (t down) -> image point (u, v), v down."""
    return (0.05 + 0.9 * s + 0.03 * math.sin(math.pi * t), 0.1 + 0.8 * t + 0.02 * s * s)


def alpha(s, t):
    """The blend in linear light: a ramp to the right edge."""
    return 1.0 if s < 0.7 else max(0.0, 1.0 - (s - 0.7) / 0.3)


def beta(s, t):
    return 0.001 * (1.0 - alpha(s, t))


def pfm(values, channels, width, height):
    """values[row][col] = tuple, rows top-down; PFM rows are bottom-up, little-endian."""
    out = bytearray(b"PF\n" if channels == 3 else b"Pf\n")
    out += f"{width} {height}\n-1.0\n".encode()
    for row in reversed(values):
        for v in row:
            out += struct.pack("<" + "f" * channels, *v)
    return bytes(out)


def png16(values, width, height):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = bytearray()
    for row in values:
        raw += b"\0" + b"".join(struct.pack(">H", max(0, min(65535, round(v * 65535)))) for v in row)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 16, 0, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def grid(fn, gw, gh):
    return [[fn(i / (gw - 1), j / (gh - 1)) for i in range(gw)] for j in range(gh)]


def xml(profile, frame=""):
    f = "".join(f"<{k}>{v}</{k}>" for k, v in FRUSTUM.items())
    return f"""<?xml version="1.0" encoding="utf-8"?>
<MPCDI profile="{profile}" geometry="1" color="1" version="2.0">
  <display>
    <buffer id="dome" xResolution="{W}" yResolution="{H}">
      <region id="p1" x="0" y="0" xsize="1" ysize="1" xResolution="{W}" yResolution="{H}">
        <frustum>{f}</frustum>{frame}
      </region>
    </buffer>
  </display>
  <files>
    <fileset region="p1">
      <geometryWarpFile><path>p1/warp.pfm</path><interpolation>linear</interpolation></geometryWarpFile>
      <alphaMap><path>p1/alpha.png</path><componentDepth>1</componentDepth><bitDepth>16</bitDepth><gammaEmbedded>{GAMMA_EMBEDDED}</gammaEmbedded></alphaMap>
      <betaMap><path>p1/beta.png</path><componentDepth>1</componentDepth><bitDepth>16</bitDepth></betaMap>
    </fileset>
  </files>
</MPCDI>
""".encode()


def blend_files():
    a = grid(lambda s, t: alpha(s, t) ** (1.0 / GAMMA_EMBEDDED), BW, BH)
    return {"p1/alpha.png": png16(a, BW, BH), "p1/beta.png": png16(grid(beta, BW, BH), BW, BH)}


def write_zip(name, files):
    with zipfile.ZipFile(os.path.join(HERE, name), "w", zipfile.ZIP_DEFLATED) as z:
        for member in sorted(files):
            info = zipfile.ZipInfo(member, date_time=(2026, 1, 1, 0, 0, 0))  # reproducible bytes
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, files[member])


def rotation(yaw, pitch, roll):
    """Body (x forward, y right, z down) from the eye frame: yaw, then pitch, then roll (CIGI)."""
    cy, sy = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
    cp, sp = math.cos(math.radians(pitch)), math.sin(math.radians(pitch))
    cr, sr = math.cos(math.radians(roll)), math.sin(math.radians(roll))
    rz = [[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]]
    ry = [[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]]
    rx = [[1, 0, 0], [0, cr, -sr], [0, sr, cr]]
    mul = lambda a, b: [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(mul(rz, ry), rx)


def direction(u, v, frustum=FRUSTUM):
    """The body-frame direction through image point (u, v) of the fixtures' camera."""
    l, r = -math.tan(math.radians(-frustum["leftAngle"])), math.tan(math.radians(frustum["rightAngle"]))
    d, up = -math.tan(math.radians(-frustum["downAngle"])), math.tan(math.radians(frustum["upAngle"]))
    x, y = 2 * u - 1, 1 - 2 * v
    eye = (1.0, 0.5 * (r - l) * x + 0.5 * (r + l), -(0.5 * (up - d) * y + 0.5 * (up + d)))
    m = rotation(frustum["yaw"], frustum["pitch"], frustum["roll"])
    b = [sum(m[i][k] * eye[k] for k in range(3)) for i in range(3)]
    n = math.sqrt(sum(c * c for c in b))
    return [c / n for c in b]


def main():
    absolute = grid(uv, GW, GH)
    write_zip("warp_absolute.mpcdi", {"mpcdi.xml": xml("3d"), "p1/warp.pfm": pfm(
        [[(u, v, 0.0) for u, v in row] for row in absolute], 3, GW, GH), **blend_files()})

    folder = os.path.join(HERE, "warp_offset")
    os.makedirs(os.path.join(folder, "p1"), exist_ok=True)
    offsets = [[(u - i / (GW - 1), v - j / (GH - 1), 0.0) for i, (u, v) in enumerate(row)] for j, row in enumerate(absolute)]
    files = {"mpcdi.xml": xml("3d"), "p1/warp.pfm": pfm(offsets, 3, GW, GH), **blend_files()}
    for member, data in files.items():
        with open(os.path.join(folder, member), "wb") as f:
            f.write(data)

    # a3: points 3 m from the eye in the surveyor's axes (x right, y forward, z up): the
    # coordinate frame's pitch axis (right) is +x, roll axis (forward) +y, yaw axis (down) -z.
    frame = ("<coordinateFrame>" + "".join(f"<pos{a}>{v}</pos{a}>" for a, v in zip("xyz", EYE)) +
             "<yawx>0</yawx><yawy>0</yawy><yawz>-1</yawz><pitchx>1</pitchx><pitchy>0</pitchy><pitchz>0</pitchz>"
             "<rollx>0</rollx><rolly>1</rolly><rollz>0</rollz></coordinateFrame>")
    points = []
    for row in absolute:
        out = []
        for u, v in row:
            fwd, right, down = direction(u, v)
            out.append((EYE[0] + 3 * right, EYE[1] + 3 * fwd, EYE[2] - 3 * down))
        points.append(out)
    write_zip("points_a3.mpcdi", {"mpcdi.xml": xml("a3", frame), "p1/warp.pfm": pfm(points, 3, GW, GH), **blend_files()})
    sdk_fixtures(absolute, points)

    with open(os.path.join(HERE, "mesh_bourke.txt"), "w") as f:
        f.write(f"2\n{GW} {GH}\n")
        aspect = W / H
        for j in reversed(range(GH)):  # bottom row first
            for i in range(GW):
                u, v = absolute[j][i]
                s, t = i / (GW - 1), j / (GH - 1)
                f.write(f"{-aspect + 2 * aspect * s:.6f} {1 - 2 * t:.6f} {u:.6f} {1 - v:.6f} {alpha(s, t):.6f}\n")


def png16_rgb(values, width, height):
    """values[row][col] = (r, g, b) in [0, 1]: a 16-bit RGB PNG (colour type 2)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = bytearray()
    for row in values:
        raw += b"\0" + b"".join(struct.pack(">H", max(0, min(65535, round(c * 65535)))) for px in row for c in px)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 16, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def sdk_pfm(values):
    """The SDK's PFM: "PF", the sizes, "-1.000000", rows bottom-up, little-endian floats."""
    out = bytearray(f"PF\n{len(values[0])} {len(values)}\n-1.000000\n".encode())
    for row in reversed(values):
        for v in row:
            out += struct.pack("<fff", *v)
    return bytes(out)


def sdk_frustum(f):
    order = ("yaw", "pitch", "roll", "rightAngle", "leftAngle", "upAngle", "downAngle")
    return "<frustum>" + "".join(f"<{k}>{f[k]:.6f}</{k}>" for k in order) + "</frustum>"


def sdk_region(rid, frustum=None, frame=""):
    return (f'<region id="{rid}" Xresolution="{W}" Yresolution="{H}" x="0" y="0" xsize="1" ysize="1">' +
            (sdk_frustum(frustum) if frustum else "") + frame + "</region>")


def sdk_fileset(rid, gamma=GAMMA_EMBEDDED, alpha_depth=1):
    return (f'<fileset region="{rid}"><geometryWarpFile><path>GeometryWarpFile-{rid}.pfm</path>'
            "<geometricUnit>mm</geometricUnit><interpolation>linear</interpolation>"
            "<originof3DData>linear</originof3DData></geometryWarpFile>"
            f"<alphaMap><path>AlphaMap-{rid}.png</path><componentDepth>{alpha_depth}</componentDepth>"
            f"<bitDepth>16</bitDepth><gammaEmbedded>{gamma:.6f}</gammaEmbedded></alphaMap>"
            f"<betaMap><path>BetaMap-{rid}.png</path><bitDepth>16</bitDepth><componentDepth>1</componentDepth>"
            "</betaMap></fileset>")


def sdk_xml(profile, regions, filesets):
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<MPCDI profile="{profile}" date="2026-01-01T00:00:00Z" level="1" version="1.0">'
            f'<display><buffer id="buffer1" Xresolution="{W}" Yresolution="{H}">{"".join(regions)}</buffer></display>'
            f'<files>{"".join(filesets)}</files></MPCDI>').encode()


def sdk_blend(rid, rgb=False):
    if rgb:
        alpha_map = png16_rgb([[tuple((k * alpha(s, t)) ** (1 / GAMMA_EMBEDDED) for k in (1.0, 0.8, 0.6))
                                for s, t in row] for row in grid(lambda s, t: (s, t), BW, BH)], BW, BH)
    else:
        alpha_map = png16(grid(lambda s, t: alpha(s, t) ** (1 / GAMMA_EMBEDDED), BW, BH), BW, BH)
    return {f"AlphaMap-{rid}.png": alpha_map, f"BetaMap-{rid}.png": png16(grid(beta, BW, BH), BW, BH)}


def sdk_fixtures(absolute, eye_points):
    uv_warp = [[(u, v, 0.0) for u, v in row] for row in absolute]
    write_zip("sdk_2d.mpcdi", {"mpcdi.xml": sdk_xml("2d", [sdk_region("r1")], [sdk_fileset("r1")]),
                               "GeometryWarpFile-r1.pfm": sdk_pfm(uv_warp), **sdk_blend("r1")})
    write_zip("sdk_3d.mpcdi", {"mpcdi.xml": sdk_xml("3d", [sdk_region("r1", FRUSTUM)], [sdk_fileset("r1", alpha_depth=3)]),
                               "GeometryWarpFile-r1.pfm": sdk_pfm(uv_warp), **sdk_blend("r1", rgb=True)})
    frame = ("<coordinateFrame>" + "".join(f"<pos{a}>{v:.6f}</pos{a}>" for a, v in zip("xyz", EYE)) +
             "<yawx>0</yawx><yawy>0</yawy><yawz>-1</yawz><pitchx>1</pitchx><pitchy>0</pitchy><pitchz>0</pitchz>"
             "<rollx>0</rollx><rolly>1</rolly><rollz>0</rollz></coordinateFrame>")
    write_zip("sdk_a3.mpcdi", {"mpcdi.xml": sdk_xml("a3", [sdk_region("r1", None, frame)], [sdk_fileset("r1", gamma=0.0)]),
                               "GeometryWarpFile-r1.pfm": sdk_pfm(eye_points), **sdk_blend("r1")})

    def object_points(frustum):  # 3 m from the origin, in the surveyor's axes of points_a3
        out = []
        for row in absolute:
            line = []
            for u, v in row:
                fwd, right, down = direction(u, v, frustum)
                line.append((3 * right, 3 * fwd, -3 * down))
            out.append(line)
        return out
    origin = frame.replace("".join(f"<pos{a}>{v:.6f}</pos{a}>" for a, v in zip("xyz", EYE)),
                           "<posx>0</posx><posy>0</posy><posz>0</posz>")
    write_zip("sdk_sl.mpcdi", {"mpcdi.xml": sdk_xml("sl", [sdk_region("r1", FRUSTUM, origin)], [sdk_fileset("r1")]),
                               "GeometryWarpFile-r1.pfm": sdk_pfm(object_points(FRUSTUM)), **sdk_blend("r1")})
    files, regions, sets = {}, [], []
    for rid, yaw in (("r1", -40.0), ("r2", 10.0), ("r3", 60.0)):
        f = dict(FRUSTUM, yaw=yaw)
        regions.append(sdk_region(rid, f, origin))
        sets.append(sdk_fileset(rid))
        files[f"GeometryWarpFile-{rid}.pfm"] = sdk_pfm(object_points(f))
        files.update(sdk_blend(rid))
    write_zip("sdk_sl_three.mpcdi", {"mpcdi.xml": sdk_xml("sl", regions, sets), **files})


if __name__ == "__main__":
    main()

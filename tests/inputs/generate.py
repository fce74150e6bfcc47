#!/usr/bin/env python3
"""Writes the bad inputs too big or too odd to keep in git (deep nesting,
huge counts, a 150,000-vertex polygon, NaN texels) into OUT_DIR; the CLI
test runs them as catalog lines named generated/NAME (tests/inputs/catalog.txt).

    tests/inputs/generate.py OUT_DIR
"""
import math
import struct
import sys
from pathlib import Path

out = Path(sys.argv[1])
out.mkdir(parents=True, exist_ok=True)


def write(name, text):
    (out / name).write_text(text)


def scene_with(obj=None, **parts):
    import json
    return json.dumps({**({"meshes": [{"obj": obj}]} if obj else {}), **parts})


# ---- JSON -------------------------------------------------------------------
depth = 100_000
write("deep-nesting.json", '{"camera": ' + "[" * depth + "]" * depth + "}")
write("far-triangle.json", scene_with(meshes=[{"positions": [[3e38, 0, 0], [3e38, 1, 0], [3e38, 0, 1]],
                                               "triangles": [[0, 1, 2]]}]))
write("far-sphere.json", scene_with(spheres=[{"center": [2e38, 0, 0], "radius": 2e38}]))
write("sphere-beyond-limit.json", scene_with(spheres=[{"center": [0, 0, 0], "radius": 1e30}]))
write("overflowing-camera.json", scene_with(camera={"position": [3e38, 0, 0], "look_at": [-3e38, 0, 0]},
                                             spheres=[{"center": [0, 0, -3], "radius": 1}]))
write("key-with-newline.json", '{"spheres": [], "camera\\nposition": 1}')
write("key-with-escape.json", '{"\\u001b[31mred": 1}')
write("long-key.json", '{"' + "k" * 1_000_000 + '": 1}')
with open(out / "oversized-scene.json", "wb") as f:  # 65 MiB: past the scene-file cap, sparse on disk
    f.write(b'{"description": "')
    f.seek(65 << 20)
    f.write(b'"}')
write("duplicate-key.json", '{\n  "camera": {"vfov": 30},\n  "camera": {"vfov": 40}\n}\n')

# ---- COLLADA ------------------------------------------------------------------
def collada(primitives='<triangles material="mat" count="1"><input semantic="VERTEX" source="#tri-vertices" offset="0"/><p>0 1 2</p></triangles>',
            vertices='<vertices id="tri-vertices"><input semantic="POSITION" source="#tri-positions"/></vertices>',
            node_inner='', extra='', camera=''):
    return f'''<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  {camera}
  <library_materials><material id="m"><instance_effect url="#e"/></material></library_materials>
  <library_effects><effect id="e"><profile_COMMON><technique sid="common"><lambert><diffuse><color>0.5 0.5 0.5 1</color></diffuse></lambert></technique></profile_COMMON></effect></library_effects>
  <library_geometries>
    <geometry id="tri"><mesh>
      <source id="tri-positions"><float_array id="a" count="9">0 0 0 1 0 0 0 1 0</float_array><technique_common><accessor source="#a" count="3" stride="3"/></technique_common></source>{vertices}
      {primitives}
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="Scene"><node id="n">{node_inner}<instance_geometry url="#tri"><bind_material><technique_common><instance_material symbol="mat" target="#m"/></technique_common></bind_material></instance_geometry></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
  {extra}
</COLLADA>
'''


nested = 50_000
write("deep-nesting.dae", collada(extra="<extra>" + "<a>" * nested + "</a>" * nested + "</extra>"))
write("vcount-overflow.dae", collada(primitives='<polylist material="mat" count="2"><input semantic="VERTEX" source="#tri-vertices" offset="0"/>'
                                                '<vcount>9223372036854775806 9223372036854775806</vcount><p>0 1 2</p></polylist>'))
write("huge-count.dae", collada(primitives='<triangles material="mat" count="300000000"><input semantic="VERTEX" source="#tri-vertices" offset="0"/><p>0 1 2</p></triangles>'))
write("negative-count.dae", collada(primitives='<triangles material="mat" count="-1"><input semantic="VERTEX" source="#tri-vertices" offset="0"/><p>0 1 2</p></triangles>'))
write("self-referring-vertices.dae", collada(vertices='<vertices id="tri-vertices"><input semantic="POSITION" source="#tri-vertices"/></vertices>'))
write("thin-aspect.dae", collada(
    camera='<library_cameras><camera id="cam"><optics><technique_common><perspective><yfov>40</yfov>'
           '<aspect_ratio>0.0005</aspect_ratio><znear>0.1</znear><zfar>100</zfar></perspective></technique_common></optics></camera></library_cameras>',
    node_inner='').replace('<node id="n">', '<node id="c"><translate>0 0 5</translate><instance_camera url="#cam"/></node><node id="n">'))
write("infinite-scale.dae", collada(node_inner="<scale>1e30 1e30 1e30</scale>"))

# ---- OBJ ----------------------------------------------------------------------
write("nan-vertex.obj", "v nan nan nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
write("nan-vertex.json", scene_with("nan-vertex.obj"))
write("quad-out-of-range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 9\n")
write("quad-out-of-range.json", scene_with("quad-out-of-range.obj"))


def polygon(name, n, star):
    lines = []
    for k in range(n):
        a = 2 * math.pi * k / n
        r = (1.0 if k % 2 == 0 else 0.5) if star else 1.0
        lines.append(f"v {r * math.cos(a):.7f} {r * math.sin(a):.7f} -3")
    lines.append("f " + " ".join(str(k + 1) for k in range(n)))
    write(name + ".obj", "\n".join(lines) + "\n")
    write(name + ".json", scene_with(name + ".obj"))


polygon("huge-concave-polygon", 150_000, star=True)    # refused: ear clipping is quadratic
polygon("huge-convex-polygon", 150_000, star=False)    # legitimate: split as a fan

# ---- legitimate extremes (rendered, not refused) -------------------------------------------
# a million point lights (25 MB): loads in seconds (nlohmann's callback parser took minutes: quadratic)
write("million-lights.json", '{"spheres": [{"center": [0, 0, -3], "radius": 1}], "lights": [' +
      ",".join(f'{{"position": [{i % 97}, 2, 0]}}' for i in range(1_000_000)) + "]}")
write("sky-sphere.json", scene_with(  # a huge sphere around the camera, lit from its centre: direct light (-m 1) is 0.5/pi x 1e18/r^2 everywhere
    materials={"wall": {"albedo": [0.5, 0.5, 0.5]}},
    spheres=[{"center": [0, 0, 0], "radius": 1e9, "material": "wall"}],
    lights=[{"position": [0, 0, 0], "intensity": [1e18, 1e18, 1e18]}]))
# an environment map (PFM: float RGB, bottom row first) with NaN, infinite and negative texels
w, h = 8, 4
texels = []
for y in range(h):
    for x in range(w):
        texels += [[math.nan, 1.0, 1.0], [math.inf, 1.0, 1.0], [-50.0, 1.0, 1.0]][x % 3] if x < 3 else [1.0, 1.0, 1.0]
with open(out / "bad-texels.pfm", "wb") as f:
    f.write(f"PF\n{w} {h}\n-1.0\n".encode())
    f.write(struct.pack(f"<{len(texels)}f", *texels))
write("bad-texels.json", scene_with(environment={"image": "bad-texels.pfm"},
                                    spheres=[{"center": [0, 0, -3], "radius": 1}]))
# an environment map with an alpha channel of 0 (PNG, RGBA): its colours count as stored, with a warning
def png_rgba(path, w, h, rgba):
    import zlib
    raw = b"".join(b"\0" + bytes(rgba) * w for _ in range(h))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
                     chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


png_rgba(out / "transparent-sky.png", 8, 4, [255, 128, 0, 0])
write("transparent-sky.json", scene_with(environment={"image": "transparent-sky.png"}))
srgb_128 = ((128 / 255 + 0.055) / 1.055) ** 2.4
with open(out / "transparent-sky-expected.pfm", "wb") as f:  # what the camera sees: the colours, never black
    f.write(b"PF\n16 12\n-1.0\n")
    f.write(struct.pack("<576f", *([1.0, srgb_128, 0.0] * 192)))
# what the camera inside the lit sphere must see: 0.5 / pi everywhere (16 x 12)
with open(out / "sky-expected.pfm", "wb") as f:
    f.write(b"PF\n16 12\n-1.0\n")
    f.write(struct.pack("<576f", *([0.5 / math.pi] * 576)))

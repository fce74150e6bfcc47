"""Runs inside Blender (blender -b --factory-startup --python tools/perf/cycles_bridge.py -- MODE ...);
tools/compare-cycles drives it. Two modes:

  render SCENE.json OUT.exr SPP SEED MAX_BOUNCES
      builds the PathLab scene in Cycles and renders it to a linear EXR;
  compare REPORT.json SCENE.json LABEL=A.exr,B.exr ...
      reads pairs of independent renders per renderer, labels each pixel by
      the shape its centre sees, and writes per-region means with their
      standard errors.

The translation is exact for what it accepts, and refuses the rest (the
orchestrator checks the scene first):
- PathLab is +y up, Blender +z up: (x, y, z) -> (x, -z, y), a rotation.
- The camera: pinhole, vertical field of view, box pixel filter one pixel wide.
- diffuse -> Diffuse BSDF (roughness 0: Lambert);
  conductor with F0 = 1 -> Glossy BSDF, GGX, white: Cycles squares the
  roughness as PathLab does (alpha = roughness^2). Blender 3.4's Glossy BSDF
  has no Fresnel (F = 1) and its masking is the separable G1(wo) G1(wi).
- spheres -> one point of a point cloud each: Cycles intersects points as
  true spheres (no tessellation).
- quads and inline triangle meshes -> meshes, flat shaded.
- a medium (task 12: extinction sigma_t = density, albedo, g) -> Volume
  Scatter (colour albedo, density sigma_t, anisotropy g: sigma_s = albedo
  sigma_t) plus Volume Absorption (colour albedo, density sigma_t:
  sigma_a = (1 - albedo) sigma_t), homogeneous; an interface -> a material
  with that volume and no surface (Cycles' index-matched boundary); the
  scene's medium -> the world's volume.
- the environment image -> the world, looked up with PathLab's own
  u = atan2(z, x) / 2 pi, v = theta / pi (math nodes, not Blender's
  equirectangular convention), nearest texel: PathLab's lighting integrates
  the map's pixels as they are (docs/scene-format.md).
"""
import json
import math
import sys

import bpy
import numpy as np
from mathutils import Matrix, Vector


def to_blender(p):
    x, y, z = p
    return (x, -z, y)


def add_volume(nodes, links, medium, socket):
    """sigma_s = albedo sigma_t (Volume Scatter: colour x density), sigma_a =
    (1 - albedo) sigma_t (Volume Absorption: (1 - colour) x density)."""
    albedo = (*medium.get("albedo", [1.0, 1.0, 1.0]), 1.0)
    scatter = nodes.new("ShaderNodeVolumeScatter")
    scatter.inputs["Color"].default_value = albedo
    scatter.inputs["Density"].default_value = medium["density"]
    scatter.inputs["Anisotropy"].default_value = medium.get("g", 0.0)
    absorb = nodes.new("ShaderNodeVolumeAbsorption")
    absorb.inputs["Color"].default_value = albedo
    absorb.inputs["Density"].default_value = medium["density"]
    both = nodes.new("ShaderNodeAddShader")
    links.new(scatter.outputs["Volume"], both.inputs[0])
    links.new(absorb.outputs["Volume"], both.inputs[1])
    links.new(both.outputs["Shader"], socket)


def scene_material(name, spec, media):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    material.cycles.homogeneous_volume = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    kind = spec.get("type", "diffuse")
    if kind == "interface":  # a volume and no surface: rays cross it unchanged
        add_volume(nodes, links, media[spec["interior"]], output.inputs["Volume"])
        return material
    if kind == "diffuse":
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (*spec.get("albedo", [0.8, 0.8, 0.8]), 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0
    elif kind == "conductor":
        bsdf = nodes.new("ShaderNodeBsdfGlossy")
        bsdf.distribution = "GGX"
        bsdf.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        bsdf.inputs["Roughness"].default_value = spec.get("roughness", 0.5)
    else:
        raise SystemExit(f"cycles_bridge: material {name!r}: type {kind!r} has no translation")
    links.new(bsdf.outputs["BSDF"], output.inputs["Surface"])
    return material


def add_mesh(name, positions, triangles, material):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([to_blender(p) for p in positions], [], [tuple(t) for t in triangles])
    mesh.materials.append(material)
    for polygon in mesh.polygons:
        polygon.use_smooth = False
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)


def add_sphere(index, center, radius, material):
    """A point cloud of one point: Cycles renders points as spheres. Made
    from a one-vertex mesh by geometry nodes (Mesh to Points)."""
    mesh = bpy.data.meshes.new(f"sphere {index}")
    mesh.from_pydata([to_blender(center)], [], [])
    obj = bpy.data.objects.new(f"sphere {index}", mesh)
    bpy.context.scene.collection.objects.link(obj)
    tree = bpy.data.node_groups.new(f"sphere {index}", "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    group_in, group_out = tree.nodes.new("NodeGroupInput"), tree.nodes.new("NodeGroupOutput")
    to_points = tree.nodes.new("GeometryNodeMeshToPoints")
    to_points.inputs["Radius"].default_value = radius
    set_material = tree.nodes.new("GeometryNodeSetMaterial")
    set_material.inputs["Material"].default_value = material
    tree.links.new(group_in.outputs["Geometry"], to_points.inputs["Mesh"])
    tree.links.new(to_points.outputs["Points"], set_material.inputs["Geometry"])
    tree.links.new(set_material.outputs["Geometry"], group_out.inputs["Geometry"])
    modifier = obj.modifiers.new("sphere", "NODES")
    modifier.node_group = tree


def add_world(environment, medium=None):
    world = bpy.data.worlds.new("environment")
    bpy.context.scene.world = world
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputWorld")
    if medium is not None:
        add_volume(nodes, links, medium, output.inputs["Volume"])
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = environment.get("scale", 1.0)
    links.new(background.outputs["Background"], output.inputs["Surface"])
    if "color" in environment:
        background.inputs["Color"].default_value = (*environment["color"], 1.0)
        return

    def math_node(operation, a, b=None):
        node = nodes.new("ShaderNodeMath")
        node.operation = operation
        for socket, value in zip(node.inputs, (a, b)):
            if value is None:
                continue
            if isinstance(value, (int, float)):
                socket.default_value = value
            else:
                links.new(value, socket)
        return node.outputs["Value"]

    # The direction in Blender's frame is (bx, by, bz) = (x, -z, y) of PathLab's.
    coordinate = nodes.new("ShaderNodeTexCoord")
    split = nodes.new("ShaderNodeSeparateXYZ")
    links.new(coordinate.outputs["Generated"], split.inputs["Vector"])  # in a world: the ray direction
    bx, by, bz = split.outputs["X"], split.outputs["Y"], split.outputs["Z"]
    # PathLab: phi = atan2(z, x) = atan2(-by, bx) in [0, 2 pi), u = phi / 2 pi;
    # theta = acos(y) = acos(bz), v = theta / pi from the top row; Blender's v is from the bottom.
    phi = math_node("ARCTAN2", math_node("MULTIPLY", by, -1.0), bx)
    u = math_node("FRACT", math_node("DIVIDE", phi, 2.0 * math.pi))
    v = math_node("SUBTRACT", 1.0, math_node("DIVIDE", math_node("ARCCOSINE", bz), math.pi))
    uv = nodes.new("ShaderNodeCombineXYZ")
    links.new(u, uv.inputs["X"])
    links.new(v, uv.inputs["Y"])
    texture = nodes.new("ShaderNodeTexImage")
    texture.image = bpy.data.images.load(environment["image"])
    texture.image.colorspace_settings.name = "Non-Color"  # the EXR's numbers, untouched
    texture.interpolation = "Closest"
    texture.extension = "REPEAT"
    links.new(uv.outputs["Vector"], texture.inputs["Vector"])
    links.new(texture.outputs["Color"], background.inputs["Color"])


def add_camera(camera):
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(camera.get("vfov", 40.0))
    obj = bpy.data.objects.new("camera", data)
    bpy.context.scene.collection.objects.link(obj)
    eye = Vector(to_blender(camera.get("position", [0, 0, 0])))
    target = Vector(to_blender(camera.get("look_at", [0, 0, -1])))
    up = Vector(to_blender(camera.get("up", [0, 1, 0]))).normalized()
    forward = (target - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    rotation = Matrix((right, true_up, -forward)).transposed()  # columns: camera x, y, z
    obj.matrix_world = Matrix.Translation(eye) @ rotation.to_4x4()
    bpy.context.scene.camera = obj


def render(scene_path, out_path, spp, seed, max_bounces):
    spec = json.load(open(scene_path))
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = spp
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = seed
    cycles.pixel_filter_type = "BOX"
    scene.render.filter_size = 1.0
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0  # "filter glossy" biases rough reflections
    cycles.caustics_reflective = cycles.caustics_refractive = True
    cycles.max_bounces = max_bounces
    cycles.diffuse_bounces = cycles.glossy_bounces = cycles.transparent_max_bounces = max_bounces
    cycles.transmission_bounces = cycles.volume_bounces = max_bounces
    render_settings = spec.get("render", {})
    scene.render.resolution_x = render_settings.get("width", 400)
    scene.render.resolution_y = render_settings.get("height", 300)
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    add_camera(spec.get("camera", {}))
    media = spec.get("media", {})
    materials = {name: scene_material(name, m, media) for name, m in spec.get("materials", {}).items()}
    if "default" not in materials:
        materials["default"] = scene_material("default", {"albedo": [0.5, 0.5, 0.5]}, media)
    for i, sphere in enumerate(spec.get("spheres", [])):
        add_sphere(i, sphere.get("center", [0, 0, 0]), sphere.get("radius", 1.0),
                   materials[sphere.get("material", "default")])
    for i, mesh in enumerate(spec.get("meshes", [])):
        material = materials[mesh.get("material", "default")]
        if "quad" in mesh:
            q = mesh["quad"]
            c, eu, ev = (np.array(q[k], dtype=float) for k in ("corner", "edge_u", "edge_v"))
            add_mesh(f"mesh {i}", [c, c + eu, c + eu + ev, c + ev], [(0, 1, 2), (0, 2, 3)], material)
        else:
            add_mesh(f"mesh {i}", mesh["positions"], mesh["triangles"], material)
    add_world(spec.get("environment", {"color": [0, 0, 0]}), media.get(spec["medium"]) if "medium" in spec else None)
    scene.render.filepath = out_path
    bpy.ops.render.render(write_still=True)
    # And a PNG to look at (sRGB, the Standard view: as PathLab writes PNGs).
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_depth = "8"
    bpy.data.images["Render Result"].save_render(out_path.rsplit(".", 1)[0] + ".png")


def read_exr(path):
    image = bpy.data.images.load(path)
    image.colorspace_settings.name = "Non-Color"
    width, height = image.size
    pixels = np.array(image.pixels[:], dtype=np.float64).reshape(height, width, 4)[::-1, :, :3]
    bpy.data.images.remove(image)
    return pixels  # row 0 at the top, as PathLab's pixel rows


def pixel_labels(spec, width, height):
    """The shape each pixel's centre sees (sphere i -> i, mesh j -> 100 + j,
    nothing -> -1), traced in PathLab's frame with its pinhole camera; a pixel
    whose four corners disagree is on an edge and gets -2."""
    camera = spec.get("camera", {})
    eye = np.array(camera.get("position", [0, 0, 0]), dtype=float)
    forward = np.array(camera.get("look_at", [0, 0, -1]), dtype=float) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, np.array(camera.get("up", [0, 1, 0]), dtype=float))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    half_h = math.tan(math.radians(camera.get("vfov", 40.0)) / 2)
    half_w = half_h * width / height

    def trace(px, py):
        sx = (2 * px / width - 1) * half_w
        sy = (1 - 2 * py / height) * half_h
        d = forward[None, :] + sx[:, None] * right[None, :] + sy[:, None] * up[None, :]
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        best = np.full(len(px), np.inf)
        label = np.full(len(px), -1)
        for i, s in enumerate(spec.get("spheres", [])):
            oc = eye - np.array(s.get("center", [0, 0, 0]), dtype=float)
            b = d @ oc
            disc = b * b - (oc @ oc - s.get("radius", 1.0) ** 2)
            t = np.where(disc >= 0, -b - np.sqrt(np.maximum(disc, 0)), np.inf)
            t = np.where(t > 1e-6, t, np.inf)
            closer = t < best
            best, label = np.where(closer, t, best), np.where(closer, i, label)
        for j, mesh in enumerate(spec.get("meshes", [])):
            if "quad" in mesh:
                q = mesh["quad"]
                c, eu, ev = (np.array(q[k], dtype=float) for k in ("corner", "edge_u", "edge_v"))
                tris = [(c, c + eu, c + eu + ev), (c, c + eu + ev, c + ev)]
            else:
                p = np.array(mesh["positions"], dtype=float)
                tris = [(p[a], p[b], p[c]) for a, b, c in mesh["triangles"]]
            for a, b, c in tris:
                e1, e2 = b - a, c - a
                pvec = np.cross(d, e2)
                det = pvec @ e1
                ok = np.abs(det) > 1e-12
                inv = np.where(ok, 1 / np.where(ok, det, 1), 0)
                tvec = eye - a
                u = (pvec @ tvec) * inv
                qvec = np.cross(tvec, e1)
                v = (d @ qvec) * inv
                t = (qvec @ e2) * inv
                hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 1e-6)
                t = np.where(hit, t, np.inf)
                closer = t < best
                best, label = np.where(closer, t, best), np.where(closer, 100 + j, label)
        return label

    ys, xs = np.mgrid[0:height, 0:width]
    xs, ys = xs.ravel().astype(float), ys.ravel().astype(float)
    centre = trace(xs + 0.5, ys + 0.5)
    for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1)):
        centre = np.where(trace(xs + dx, ys + dy) == centre, centre, -2)
    return centre.reshape(height, width)


def compare(report_path, scene_path, runs):
    spec = json.load(open(scene_path))
    renders = {}
    for run in runs:
        label, files = run.split("=", 1)
        first, second = (read_exr(f) for f in files.split(","))
        renders[label] = (first, second)
    height, width = next(iter(renders.values()))[0].shape[:2]
    labels = pixel_labels(spec, width, height)
    regions = {}
    for value in sorted(set(labels.ravel()) - {-2}):
        mask = labels == value
        entry = {"pixels": int(mask.sum())}
        for name, (first, second) in renders.items():
            mean, stderr = mean_and_stderr(first[mask], second[mask])
            entry[name] = {"mean": mean.tolist(), "stderr": stderr.tolist()}
        regions[int(value)] = entry
    json.dump({"width": width, "height": height, "regions": regions, "blocks": block_scores(renders, labels)},
              open(report_path, "w"), indent=1)
    # A picture to look at: each renderer's average, top to bottom, then each
    # PathLab average minus Cycles' (red: PathLab brighter, blue: darker,
    # full at a difference of 0.1 in luminance).
    averages = {name: (first + second) / 2 for name, (first, second) in renders.items()}
    rows = [srgb(image) for image in averages.values()]
    for name, image in averages.items():
        if name != "cycles":
            diff = (image - averages["cycles"]) @ np.array([0.2126, 0.7152, 0.0722]) / 0.1
            rows.append(np.stack([np.clip(diff, 0, 1), np.zeros_like(diff), np.clip(-diff, 0, 1)], axis=-1))
    write_png(report_path.rsplit(".", 1)[0] + ".png", np.concatenate(rows, axis=0))


def mean_and_stderr(a, b):
    """Two independent renders' pixels (N x 3): the mean of both, and the
    standard error of that mean from their difference (independent pixels)."""
    return ((a + b) / 2).mean(axis=0), np.sqrt(((a - b) ** 2).mean(axis=0)) / 2 / math.sqrt(len(a))


def block_scores(renders, labels, size=10):
    """Finer than a region, where an error in one part of a shape can cancel
    another: the image in size x size blocks (edge pixels and the background
    left out; blocks with fewer than half their pixels kept are skipped), and
    for each PathLab render against Cycles the z of every block and channel,
    as the regions' z. Under agreement they are about standard normal: a
    share of 0.27 % beyond 3 is expected by chance."""
    height, width = labels.shape
    keep = labels >= 0
    scores = {}
    for name, (first, second) in renders.items():
        if name == "cycles":
            continue
        zs = []
        for y in range(0, height - size + 1, size):
            for x in range(0, width - size + 1, size):
                block = np.s_[y:y + size, x:x + size]
                mask = keep[block]
                if 2 * int(mask.sum()) < size * size:
                    continue
                (mean_p, se_p), (mean_c, se_c) = (mean_and_stderr(a[block][mask], b[block][mask])
                                                  for a, b in ((first, second), renders["cycles"]))
                zs.extend(((mean_p - mean_c) / np.maximum(np.hypot(se_p, se_c), 1e-12)).tolist())
        zs = np.array(zs)
        scores[name] = {"size": size, "count": int(zs.size), "max_abs_z": float(np.abs(zs).max()) if zs.size else 0.0,
                        "rms_z": float(np.sqrt((zs ** 2).mean())) if zs.size else 0.0,
                        "beyond_3": int((np.abs(zs) > 3).sum())}
    return scores


def srgb(linear):
    c = np.clip(linear, 0, 1)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)


def write_png(path, pixels):
    height, width = pixels.shape[:2]
    image = bpy.data.images.new("picture", width, height, alpha=True)
    rgba = np.concatenate([pixels, np.ones((height, width, 1))], axis=-1)[::-1]  # Blender's rows go up
    image.pixels.foreach_set(rgba.astype(np.float32).ravel())
    image.filepath_raw = path
    image.file_format = "PNG"
    image.save()


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    if args[0] == "render":
        render(args[1], args[2], int(args[3]), int(args[4]), int(args[5]))
    elif args[0] == "compare":
        compare(args[1], args[2], args[3:])
    else:
        raise SystemExit(f"cycles_bridge: unknown mode {args[0]!r}")


main()

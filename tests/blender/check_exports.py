"""Opens Mocap Studio's exports with Blender's own importers and checks what Blender sees.

    blender -b --factory-startup --python-exit-code 1 --python check_exports.py -- \
        TAKE.bvh FRAME.obj CACHE.pc2 [SAMPLE]

TAKE.bvh goes through the BVH importer: one bone per joint, one key per frame, and the posed
marker bones sit where the BVH channels put them. FRAME.obj (one file of an OBJ sequence) goes
through the OBJ importer with the vertices of the file. CACHE.pc2's rest mesh (CACHE.obj) gets a
Mesh Cache modifier on the cache; stepping the scene frames must give the cache's vertices.
SAMPLE (optional) is the cache sample FRAME.obj was written from, so the two exports agree.
With `--glb RIG.glb WEIGHTS.csv`, the blendshape rig `mocap solve` wrote goes through the glTF
importer: its shape keys and their keyed values must match the weight curves of the same solve.
With `--mocap MOCAP` as well, Blender exports the imported rig again as GLB (shape keys as morph
targets) and `mocap rig` must read that file: the same shape names, and the neutral with the
vertices and triangles Blender wrote.
Prints "PASS: ..." and exits 0, or "FAIL: ..." and exits 1.
"""

# Compatibility shims for Debian's Blender 3.4 under Python 3.11 / numpy 1.24. They come first,
# before any importer runs: the BVH importer opens its file with mode 'rU' (the 'U' flag is gone
# in Python 3.11), and the glTF add-on, loaded with the default add-ons, uses numpy.bool (removed in
# numpy 1.24).
import builtins

_builtin_open = builtins.open


def _open_without_universal_newlines(file, mode="r", *args, **kwargs):
    if isinstance(mode, str) and "U" in mode:
        mode = mode.replace("U", "") or "r"
    return _builtin_open(file, mode, *args, **kwargs)


builtins.open = _open_without_universal_newlines

try:
    import numpy
except ImportError:  # no numpy (python3-numpy is only recommended): nothing to patch
    numpy = None
if numpy is not None and not hasattr(numpy, "bool"):
    numpy.bool = bool

import json  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import struct  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402

import bpy  # noqa: E402
from mathutils import Matrix, Vector  # noqa: E402


class CheckFailed(Exception):
    pass


def require(condition, message):
    if not condition:
        raise CheckFailed(message)


def tolerance(points):
    """Absolute tolerance for coordinates: float32 rounding relative to the data's extent."""
    extent = max((abs(c) for p in points for c in p), default=1.0)
    return 1e-5 * max(extent, 1.0)


def close(a, b, tol):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


# --- the files as written ---------------------------------------------------------------------

def read_pc2(path):
    with open(path, "rb") as f:
        data = f.read()
    magic, version, points, start, rate, samples = struct.unpack_from("<12siiffi", data, 0)
    require(magic == b"POINTCACHE2\0" and version == 1, f"{path}: not a PC2 version 1 file")
    require(len(data) == 32 + 12 * points * samples, f"{path}: size does not match its header")
    floats = struct.unpack_from(f"<{3 * points * samples}f", data, 32)
    return [[floats[3 * (s * points + i):3 * (s * points + i) + 3] for i in range(points)] for s in range(samples)]


def read_obj_vertices(path):
    with open(path) as f:
        return [tuple(float(t) for t in line.split()[1:4]) for line in f if line.startswith("v ")]


class Bvh:
    """Joints (name, OFFSET, channel names, parent index) and motion rows of a BVH file."""

    def __init__(self, path):
        with open(path) as f:
            tokens = f.read().split()
        nodes, stack, i = [], [], 0  # nodes include End Sites, which have no channels
        while tokens[i] != "MOTION":
            t = tokens[i]
            if t in ("ROOT", "JOINT", "End"):
                nodes.append({"name": tokens[i + 1], "parent": stack[-1] if stack else None, "end": t == "End",
                              "channels": [], "offset": (0.0, 0.0, 0.0)})
                i += 2
            elif t == "{":
                stack.append(len(nodes) - 1)
                i += 1
            elif t == "}":
                stack.pop()
                i += 1
            elif t == "OFFSET":
                nodes[-1]["offset"] = tuple(float(v) for v in tokens[i + 1:i + 4])
                i += 4
            elif t == "CHANNELS":
                n = int(tokens[i + 1])
                nodes[-1]["channels"] = tokens[i + 2:i + 2 + n]
                i += 2 + n
            else:
                i += 1
        joint_of = {}
        self.joints, start = [], 0
        for n, node in enumerate(nodes):
            if node["end"]:
                continue
            joint_of[n] = len(self.joints)
            node["parent"] = joint_of[node["parent"]] if node["parent"] is not None else None
            node["start"] = start
            start += len(node["channels"])
            self.joints.append(node)
        count = int(tokens[i + 2])
        i += 6  # MOTION Frames: N Frame Time: T
        self.frames = [[float(t) for t in tokens[i + f * start:i + (f + 1) * start]] for f in range(count)]

    def local_matrix(self, joint, frame):
        """The joint's transform at `frame`: its position channels (or OFFSET), then its rotations
        in channel order, as Blender's importer applies them."""
        row = self.frames[frame][joint["start"]:joint["start"] + len(joint["channels"])]
        values = dict(zip(joint["channels"], row))
        position = Vector(joint["offset"])
        for axis, name in enumerate(("Xposition", "Yposition", "Zposition")):
            if name in values:
                position[axis] = values[name]
        m = Matrix.Translation(position)
        for name in joint["channels"]:
            if name.endswith("rotation"):
                m = m @ Matrix.Rotation(math.radians(values[name]), 4, name[0])
        return m

    def world_position(self, index, frame):
        m, j = Matrix.Identity(4), index
        while j is not None:
            m = self.local_matrix(self.joints[j], frame) @ m
            j = self.joints[j]["parent"]
        return m.translation


# --- the checks -------------------------------------------------------------------------------

def imported_object(before):
    new = [o for o in bpy.context.scene.objects if o.name not in before]
    require(len(new) >= 1, "the importer created no object")
    return new


def check_bvh(path):
    bvh = Bvh(path)
    before = {o.name for o in bpy.context.scene.objects}
    # forward Y, up Z: Blender's own axes, so the file's coordinates are kept as they are.
    bpy.ops.import_anim.bvh(filepath=path, axis_forward="Y", axis_up="Z", frame_start=1, use_fps_scale=False)
    armatures = [o for o in imported_object(before) if o.type == "ARMATURE"]
    require(len(armatures) == 1, "the BVH import made no armature")
    arm = armatures[0]
    require(len(arm.data.bones) == len(bvh.joints),
            f"{len(arm.data.bones)} bones for {len(bvh.joints)} BVH joints")
    fcurve = arm.animation_data.action.fcurves[0]
    require(len(fcurve.keyframe_points) == len(bvh.frames),
            f"{len(fcurve.keyframe_points)} keys for {len(bvh.frames)} BVH frames")
    scene = bpy.context.scene
    frames = sorted({0, len(bvh.frames) // 2, len(bvh.frames) - 1})
    markers = list(range(1, len(bvh.joints)))[:: max(1, len(bvh.joints) // 5)]
    expected = {(f, m): bvh.world_position(m, f) for f in frames for m in markers}
    tol = 1e-4 * max(1.0, max(abs(c) for p in expected.values() for c in p))
    moved = False
    for f in frames:
        scene.frame_set(1 + f)
        for m in markers:
            got = arm.matrix_world @ arm.pose.bones[bvh.joints[m]["name"]].head
            require(close(got, expected[(f, m)], tol),
                    f"BVH frame {f}, {bvh.joints[m]['name']}: Blender has {tuple(got)}, the file {tuple(expected[(f, m)])}")
            moved |= not close(expected[(f, m)], expected[(frames[0], m)], tol)
    require(moved, "the BVH markers do not move over the checked frames")
    return f"BVH {len(bvh.joints)} joints x {len(bvh.frames)} frames"


def import_obj(path):
    before = {o.name for o in bpy.context.scene.objects}
    if hasattr(bpy.ops.wm, "obj_import"):  # the C++ importer (Blender 3.3 and later)
        bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    else:
        bpy.ops.import_scene.obj(filepath=path, axis_forward="Y", axis_up="Z", split_mode="OFF")
    meshes = [o for o in imported_object(before) if o.type == "MESH"]
    require(len(meshes) == 1, f"{path}: the OBJ import made {len(meshes)} meshes")
    return meshes[0]


def world_vertices(ob, mesh=None):
    mesh = mesh or ob.data
    return [tuple(ob.matrix_world @ v.co) for v in mesh.vertices]


def check_obj(path):
    ob = import_obj(path)
    written = read_obj_vertices(path)
    got = world_vertices(ob)
    require(len(got) == len(written), f"{path}: Blender has {len(got)} vertices, the file {len(written)}")
    tol = tolerance(written)
    bad = [i for i, (g, w) in enumerate(zip(got, written)) if not close(g, w, tol)]
    require(not bad, f"{path}: {len(bad)} vertices differ, first #{bad[:1]}")
    return ob, f"OBJ {len(got)} vertices, {len(ob.data.polygons)} faces"


def check_pc2(path, sequence_frame=None, sample_of_frame=None):
    cache = read_pc2(path)
    ob, _ = check_obj(os.path.splitext(path)[0] + ".obj")
    modifier = ob.modifiers.new("Mocap cache", "MESH_CACHE")
    modifier.cache_format = "PC2"
    modifier.filepath = path
    modifier.frame_start = 1.0  # scene frame 1 shows the first sample
    scene = bpy.context.scene
    samples = sorted({0, len(cache) // 2, len(cache) - 1})
    tol = tolerance(cache[0])
    vertices = sorted({0, len(cache[0]) // 3, len(cache[0]) - 1})
    seen = []
    for s in samples:
        scene.frame_set(1 + s)
        evaluated = ob.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = evaluated.to_mesh()
        got = [tuple(mesh.vertices[i].co) for i in range(len(mesh.vertices))]
        evaluated.to_mesh_clear()
        require(len(got) == len(cache[s]), f"Mesh Cache: {len(got)} vertices, the PC2 {len(cache[s])}")
        bad = [i for i in range(len(got)) if not close(got[i], cache[s][i], tol)]
        require(not bad, f"Mesh Cache sample {s}: {len(bad)} vertices differ from the PC2, first #{bad[0] if bad else ''}"
                f" ({got[bad[0]] if bad else ''} vs {cache[s][bad[0]] if bad else ''})")
        seen.append([got[i] for i in vertices])
    require(any(not close(a, b, tol) for a, b in zip(seen[0], seen[-1])),
            "the Mesh Cache modifier does not move the mesh between the first and last sample")
    if sequence_frame is not None:
        sequence = read_obj_vertices(sequence_frame)
        require(all(close(a, b, 1e-4 * max(1.0, max(abs(c) for c in a))) for a, b in zip(sequence, cache[sample_of_frame])),
                f"{sequence_frame} differs from PC2 sample {sample_of_frame}")
    return f"PC2 {len(cache)} samples x {len(cache[0])} points through the Mesh Cache modifier"


def read_weights_csv(path):
    """`mocap solve`'s plain weight curves: Frame,Time,<shape>,... and one row per frame."""
    with open(path) as f:
        rows = [line.rstrip("\n").split(",") for line in f if line.strip()]
    return rows[0][2:], [[float(v) for v in row[2:]] for row in rows[1:]]


def check_glb(path, csv_path):
    """The rig GLB through Blender's glTF importer: one shape key per shape, named as in the CSV,
    and the keyed values equal the CSV's weights (float32 in the file, so within 1e-5)."""
    names, weights = read_weights_csv(csv_path)
    before = {o.name for o in bpy.context.scene.objects}
    bpy.ops.import_scene.gltf(filepath=path)
    meshes = [o for o in imported_object(before) if o.type == "MESH"]
    require(len(meshes) == 1, f"the GLB gave {len(meshes)} mesh objects, not 1")
    key = meshes[0].data.shape_keys
    require(key is not None, "the imported mesh has no shape keys")
    blocks = [b.name for b in key.key_blocks][1:]  # the first block is the basis
    require(blocks == names, f"shape keys {blocks} differ from the CSV's columns {names}")
    action = key.animation_data.action if key.animation_data else None
    require(action is not None, "the shape keys are not animated")
    checked = 0
    for s, name in enumerate(names):
        curve = action.fcurves.find(f'key_blocks["{name}"].value')
        require(curve is not None, f"shape key {name} has no animation curve")
        values = [k.co[1] for k in curve.keyframe_points]
        require(len(values) == len(weights), f"{name}: {len(values)} keys for {len(weights)} frames")
        for f in range(0, len(weights), max(1, len(weights) // 7)):
            require(abs(values[f] - weights[f][s]) <= 1e-5,
                    f"{name} frame {f}: Blender keys {values[f]}, the CSV has {weights[f][s]}")
            checked += 1
    return names, f"GLB: {len(names)} shape keys, {checked} keyed values equal the CSV within 1e-5"


def read_glb_json(path):
    """The JSON chunk of a GLB file."""
    with open(path, "rb") as f:
        data = f.read()
    magic, version = struct.unpack_from("<4sI", data, 0)
    require(magic == b"glTF" and version == 2, f"{path}: not a GLB version 2 file")
    length, kind = struct.unpack_from("<II", data, 12)
    require(kind == 0x4E4F534A, f"{path}: the first chunk is not JSON")
    return json.loads(data[20:20 + length])


def morph_mesh(gltf, path):
    """The first mesh with morph targets, its vertex count (all primitives) and its triangle count."""
    for mesh in gltf.get("meshes", []):
        primitives = mesh["primitives"]
        if any(p.get("targets") for p in primitives):
            vertices = sum(gltf["accessors"][p["attributes"]["POSITION"]]["count"] for p in primitives)
            triangles = sum(gltf["accessors"][p["indices"]]["count"] // 3 if "indices" in p else
                            gltf["accessors"][p["attributes"]["POSITION"]]["count"] // 3 for p in primitives)
            return mesh, vertices, triangles
    raise CheckFailed(f"{path}: no mesh with morph targets")


def check_blender_glb_read_back(mocap, names, out_dir):
    """Blender's own GLB export of the imported rig, read by `mocap rig`."""
    path = os.path.join(out_dir, "blender_export.glb")
    bpy.ops.export_scene.gltf(filepath=path, export_format="GLB", export_morph=True)
    mesh, vertices, triangles = morph_mesh(read_glb_json(path), path)
    require(mesh.get("extras", {}).get("targetNames") == names,
            f"Blender wrote target names {mesh.get('extras', {}).get('targetNames')}, not {names}")
    run = subprocess.run([mocap, "rig", "--mesh", path, "-o", os.path.join(out_dir, "blender_again.glb"), "--json"],
                         capture_output=True, text=True)
    require(run.returncode == 0, f"mocap rig could not read Blender's GLB: {run.stderr.strip()}")
    report = json.loads(run.stdout)
    require(report["shapes"] == names, f"mocap rig read shapes {report['shapes']} from Blender's GLB, not {names}")
    require(report["vertices"] == vertices,
            f"mocap rig read {report['vertices']} vertices, Blender wrote {vertices}")
    require(report["triangles"] == triangles,
            f"mocap rig read {report['triangles']} triangles, Blender wrote {triangles}")
    require(report["moved_vertices"] > 0, "no shape of Blender's GLB moves a vertex")
    return (f"Blender's GLB export ({vertices} vertices, {triangles} triangles, {len(names)} morph targets) "
            f"read back by mocap rig with the same names")


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    glb, mocap = None, None
    if "--glb" in args:
        at = args.index("--glb")
        glb, args = args[at + 1:at + 3], args[:at] + args[at + 3:]
        require(len(glb) == 2, "--glb needs RIG.glb WEIGHTS.csv")
    if "--mocap" in args:
        at = args.index("--mocap")
        require(at + 1 < len(args) and glb, "--mocap needs MOCAP, and --glb")
        mocap, args = args[at + 1], args[:at] + args[at + 2:]
    if len(args) not in (3, 4):
        raise CheckFailed("usage: blender -b --python check_exports.py -- TAKE.bvh FRAME.obj CACHE.pc2 [SAMPLE]"
                          " [--glb RIG.glb WEIGHTS.csv [--mocap MOCAP]]")
    bvh, frame_obj, pc2 = args[:3]
    sample = int(args[3]) if len(args) == 4 else None
    bpy.ops.wm.read_factory_settings(use_empty=True)
    results = [check_bvh(bvh), check_obj(frame_obj)[1], check_pc2(pc2, frame_obj if sample is not None else None, sample)]
    if glb:
        names, result = check_glb(*glb)
        results.append(result)
        if mocap:
            results.append(check_blender_glb_read_back(mocap, names, os.path.dirname(os.path.abspath(glb[0]))))
    print(f"PASS: Blender {bpy.app.version_string} opened the exports: " + "; ".join(results))


try:
    main()
except CheckFailed as e:
    print(f"FAIL: {e}")
    sys.exit(1)
except Exception as e:  # an importer error is a failure too, never a pass
    import traceback

    traceback.print_exc()
    print(f"FAIL: {type(e).__name__}: {e}")
    sys.exit(1)

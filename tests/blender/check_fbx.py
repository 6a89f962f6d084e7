"""Opens Mocap Studio's FBX exports with Blender's own FBX importer and checks what Blender sees.

    blender -b --factory-startup --python-exit-code 1 --python check_fbx.py -- \
        --markers TAKE.fbx TAKE.csv UP \
        --rig RIG.fbx WEIGHTS.csv

--markers: TAKE.fbx is `mocap convert` of a take, TAKE.csv the same take as `mocap convert` writes
CSV in mm (Frame,Time,<label>:X,<label>:Y,<label>:Z,… with empty cells in gaps) and UP the axis
the FBX declares (y or z). Blender must make one empty per marker, and each empty must sit at the
marker's CSV position within 0.01 mm at every frame where the marker is valid, after Blender has
applied the file's unit scale (whatever unit the FBX is in) and turned its axes into Blender's.
--rig: RIG.fbx is `mocap solve -o RIG.fbx`, WEIGHTS.csv the same solve's weight curves. Blender
must make one shape key per CSV column (the rig's shapes) besides the basis, and each key's value
must equal the CSV weight within 1e-4 at every frame.
--tolerance T: the files after it were written with key reduction (`--reduce T`): each marker may
stray T mm further and each weight T further (the reduced curve's linear interpolation, as Blender
evaluates it, stays within T of every frame).
Prints "PASS: ..." and exits 0, or "FAIL: ..." and exits 1.
"""

import csv
import sys

import bpy
from mathutils import Vector


class CheckFailed(Exception):
    pass


# The key reduction tolerance of the files being checked (--tolerance), 0 for every frame keyed.
reduction = {"tolerance": 0.0}


def require(condition, message):
    if not condition:
        raise CheckFailed(message)


def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def import_fbx(path):
    result = bpy.ops.import_scene.fbx(filepath=path)
    require(result == {"FINISHED"}, "%s: the FBX importer returned %s" % (path, result))


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def blender_frame(sample):
    """Blender's FBX importer puts FBX time 0 at frame 1."""
    return 1 + sample


def to_blender_axes(xyz, up):
    """A position of the file in Blender's Z-up world: Y-up files turn (x, y, z) into (x, −z, y)."""
    x, y, z = xyz
    return Vector((x, -z, y)) if up == "y" else Vector((x, y, z))


def check_markers(fbx_path, csv_path, up):
    reset()
    import_fbx(fbx_path)
    header, rows = read_csv(csv_path)
    labels = [header[c][:-2] for c in range(2, len(header), 3)]
    empties = {o.name: o for o in bpy.data.objects if o.type == "EMPTY"}
    require(len(empties) == len(labels) + 1,
            "%d empties for %d markers and the root" % (len(empties), len(labels)))
    scene = bpy.context.scene
    metres_to_mm = 1000.0 / scene.unit_settings.scale_length
    worst = (0.0, "", 0)
    checked = 0
    for sample, row in enumerate(rows):
        scene.frame_set(blender_frame(sample))
        for m, label in enumerate(labels):
            cells = row[2 + 3 * m: 5 + 3 * m]
            if any(cell == "" for cell in cells):
                continue  # a gap: the FBX holds the marker there, nothing to compare
            require(label in empties, "no empty named %r" % label)
            seen = empties[label].matrix_world.translation * metres_to_mm
            error = (seen - to_blender_axes([float(c) for c in cells], up)).length
            checked += 1
            if error > worst[0]:
                worst = (error, label, sample)
    require(checked > 0, "no marker sample compared")
    limit = 0.01 + reduction["tolerance"]
    require(worst[0] <= limit, "marker %s at sample %d is %.4g mm off" % (worst[1], worst[2], worst[0]))
    print("PASS: %s: %d empties, %d valid samples within %.2g mm (largest error)"
          % (fbx_path, len(empties), checked, worst[0]))


def shape_key_curves(key):
    """Each shape key's F-curve on its value, by key name."""
    action = key.animation_data.action if key.animation_data else None
    require(action is not None, "the shape keys have no animation")
    curves = {}
    for fcurve in action.fcurves:
        if fcurve.data_path.startswith('key_blocks["') and fcurve.data_path.endswith('"].value'):
            curves[fcurve.data_path[len('key_blocks["'):-len('"].value')]] = fcurve
    return curves


def check_rig(fbx_path, csv_path):
    reset()
    import_fbx(fbx_path)
    header, rows = read_csv(csv_path)
    names = header[2:]
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    require(len(meshes) == 1, "%d meshes" % len(meshes))
    key = meshes[0].data.shape_keys
    require(key is not None, "the mesh has no shape keys")
    blocks = [b.name for b in key.key_blocks]
    require(blocks[1:] == names, "shape keys %s, weight columns %s" % (blocks[1:6], names[:5]))
    require(any(o.type == "ARMATURE" for o in bpy.data.objects), "no armature from the root bone")
    curves = shape_key_curves(key)
    worst = (0.0, "", 0)
    for s, name in enumerate(names):
        require(name in curves, "no animation on shape key %r" % name)
        fcurve = curves[name]
        for sample, row in enumerate(rows):
            error = abs(fcurve.evaluate(blender_frame(sample)) - float(row[2 + s]))
            if error > worst[0]:
                worst = (error, name, sample)
    limit = 1e-4 + reduction["tolerance"]
    require(worst[0] <= limit, "shape key %s at sample %d is %.3g off" % (worst[1], worst[2], worst[0]))
    keys = sum(len(curves[name].keyframe_points) for name in names)
    print("PASS: %s: %d shape keys, %d frames each within %.2g (largest error), %d keys in Blender"
          % (fbx_path, len(names), len(rows), worst[0], keys))


def main(argv):
    try:
        args = argv[argv.index("--") + 1:] if "--" in argv else []
        require(args, __doc__)
        while args:
            option = args.pop(0)
            if option == "--markers":
                fbx_path, csv_path, up = args[:3]
                del args[:3]
                check_markers(fbx_path, csv_path, up)
            elif option == "--rig":
                fbx_path, csv_path = args[:2]
                del args[:2]
                check_rig(fbx_path, csv_path)
            elif option == "--tolerance":
                reduction["tolerance"] = float(args.pop(0))
            else:
                raise CheckFailed("unknown option %s" % option)
    except CheckFailed as failure:
        print("FAIL: %s" % failure)
        sys.exit(1)


main(sys.argv)

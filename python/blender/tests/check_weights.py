"""Installs the Mocap Studio add-on zip in Blender, imports the bundled rig's GLB and keys its shape
keys from solved weights with File ▸ Import ▸ Mocap Solved Weights, then checks the keys.

    blender -b --factory-startup --python-exit-code 1 --python check_weights.py -- \
        ZIP RIG.glb W.csv LL.csv TAKE BINDING

W.csv is `mocap solve -o W.csv` of TAKE with BINDING (the rig's own shape names: imported by name);
LL.csv is the same solve as Live Link Face CSV, imported through the shipped arkit_to_ict map by the
mocap module (which must import inside Blender); then the Mocap panel's Solve onto Shape Keys
solves TAKE itself. Every keyed value must equal its curve (the panel's: W.csv's) within 1e-6 at
every frame (the panel's within 1e-5, as test_solve.py compares mocap.solve with the CSV). Prints
PASS/FAIL lines; exits 1 on failure.
"""

import csv
import sys

import bpy


class CheckFailed(Exception):
    pass


def require(condition, message):
    if not condition:
        raise CheckFailed(message)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0][2:], [[float(v) for v in row[2:]] for row in rows[1:]]


def check_keys(mesh, names, rows, what, tolerance=1e-6):
    """Every shape key named as a curve is keyed with the curve's values at frames 1, 2, …"""
    blocks = mesh.data.shape_keys.key_blocks
    action = mesh.data.shape_keys.animation_data.action
    curves = {c.data_path: c for c in action.fcurves}
    keyed = [n for n in names if n in blocks]
    require(len(keyed) > 0 and len(curves) == len(keyed), "%s: %d curves for %d matching shape keys"
            % (what, len(curves), len(keyed)))
    worst = 0.0
    for c, name in enumerate(names):
        if name not in blocks:
            continue
        curve = curves['key_blocks["%s"].value' % name]
        require(len(curve.keyframe_points) == len(rows), "%s: %s has %d keys for %d frames"
                % (what, name, len(curve.keyframe_points), len(rows)))
        for i, row in enumerate(rows):
            worst = max(worst, abs(curve.evaluate(1 + i) - row[c]))
    require(worst <= tolerance, "%s: a key is %.3g off its weight" % (what, worst))
    return len(keyed), worst


def main(zip_path, rig_path, weights_path, live_link_path, take_path, binding_path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="mocap_studio")
    import numpy
    # Debian's Blender 3.4 glTF importer still uses numpy.bool, which Debian's NumPy 1.24 removed:
    # the enabled add-on puts it back (mocap_studio/numpy_compat.py), so the import below works.
    require(hasattr(numpy, "bool"), "numpy.bool is missing with the add-on enabled: the glTF import would fail")
    bpy.ops.import_scene.gltf(filepath=rig_path)
    meshes = [o for o in bpy.data.objects if o.type == "MESH" and o.data.shape_keys]
    require(len(meshes) == 1, "%d meshes with shape keys in %s" % (len(meshes), rig_path))
    mesh = meshes[0]
    bpy.context.view_layer.objects.active = mesh

    result = bpy.ops.import_anim.mocap_weights(filepath=weights_path)
    require(result == {"FINISHED"}, "importing the weights CSV returned %s" % result)
    names, rows = read_csv(weights_path)
    count, worst = check_keys(mesh, names, rows, "weights CSV")
    print("PASS: weights CSV onto %s: %d shape keys × %d frames within %.2g" % (mesh.name, count, len(rows), worst))

    from mocap_studio import take_source
    mocap = take_source.import_mocap_module()
    require(mocap is not None, "import mocap failed inside Blender")
    result = bpy.ops.import_anim.mocap_weights(filepath=live_link_path, retarget_map="arkit_to_ict")
    require(result == {"FINISHED"}, "importing the Live Link CSV returned %s" % result)
    curves, values = read_csv(live_link_path)
    names, mapped = mocap.retarget_weights(curves, numpy.array(values), "arkit_to_ict")
    count, worst = check_keys(mesh, list(names), mapped.tolist(), "Live Link CSV through arkit_to_ict")
    print("PASS: Live Link CSV through arkit_to_ict: %d shape keys within %.2g" % (count, worst))

    scene = bpy.context.scene
    scene.mocap_take, scene.mocap_rig, scene.mocap_binding = take_path, rig_path, binding_path
    result = bpy.ops.mocap.solve_shape_keys()
    require(result == {"FINISHED"}, "the panel's solve returned %s" % result)
    names, rows = read_csv(weights_path)  # mocap solve's own weights, shortest round-trip numbers
    count, worst = check_keys(mesh, names, rows, "the panel's solve", 1e-5)
    print("PASS: Solve onto Shape Keys: %d shape keys equal mocap solve's weights within %.2g" % (count, worst))

    try:  # an operator that reports an error raises it when called from a script
        result = bpy.ops.import_anim.mocap_weights(filepath=live_link_path)
    except RuntimeError as error:
        result = str(error)
    require("no curve names a shape key" in str(result), "Live Link curves by name onto ICT shape keys: %s, "
            "not refused" % result)
    print("PASS: Live Link curves without a map match no ICT shape key and are refused")


try:
    args = sys.argv[sys.argv.index("--") + 1:]
    main(*args)
except CheckFailed as failure:
    print("FAIL: %s" % failure)
    sys.exit(1)

"""Installs the Mocap Studio add-on zip in Blender, imports a take with it and checks the empties.

    blender -b --factory-startup --python-exit-code 1 --python check_addon.py -- ZIP TAKE TAKE.csv MODE

TAKE.csv is `mocap convert TAKE TAKE.csv` (mm, empty cells in gaps): the truth. MODE is `module`
(the add-on must use the mocap Python module, which must import inside Blender and read the take
itself, and the empties carry the sample states) or `cli` (the module is not reachable: the add-on
must fall back to the command line). Every empty must sit within 0.01 mm of its marker at every
frame the marker was seen and be hidden in its gaps. Prints PASS/FAIL lines; exits 1 on failure.
"""

import csv
import sys

import bpy


class CheckFailed(Exception):
    pass


def require(condition, message):
    if not condition:
        raise CheckFailed(message)


def main(zip_path, take_path, csv_path, mode):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="mocap_studio")
    from mocap_studio import take_source
    module = take_source.import_mocap_module()
    if mode == "module":
        require(module is not None, "import mocap failed inside Blender")
        take = module.read(take_path)
        print("PASS: import mocap inside Blender %s: %r" % (bpy.app.version_string, take))
    else:
        require(module is None, "the module was reachable; the command-line fallback is not tested")
    result = bpy.ops.import_scene.mocap_take(filepath=take_path)
    require(result == {"FINISHED"}, "the importer returned %s" % result)

    with open(csv_path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    labels = [header[c][:-2] for c in range(2, len(header), 3)]
    empties = {o.name: o for o in bpy.data.objects if o.type == "EMPTY"}
    require(len(empties) == len(labels) + 1, "%d empties for %d markers and the root" % (len(empties), len(labels)))
    scene = bpy.context.scene
    metres = scene.unit_settings.scale_length
    worst, checked, hidden = 0.0, 0, 0
    for sample, row in enumerate(body):
        scene.frame_set(1 + sample)
        for m, label in enumerate(labels):
            empty = empties[label]
            cells = row[2 + 3 * m: 5 + 3 * m]
            if "" in cells:
                require(empty.hide_viewport, "%s is shown in its gap at sample %d" % (label, sample))
                hidden += 1
                continue
            require(not empty.hide_viewport, "%s is hidden at seen sample %d" % (label, sample))
            seen = empty.matrix_world.translation * metres * 1000.0
            error = max(abs(seen[a] - float(cells[a])) for a in range(3))
            worst = max(worst, error)
            checked += 1
    require(worst <= 0.01, "an empty is %.4g mm off its marker" % worst)
    if mode == "module":
        states = [e.get("mocap_states") for e in empties.values() if e.parent]
        require(all(s is not None and len(s) == len(body) for s in states), "sample states missing")
    print("PASS: %s mode: %d empties, %d seen samples within %.2g mm, %d gap samples hidden"
          % (mode, len(empties), checked, worst, hidden))


try:
    args = sys.argv[sys.argv.index("--") + 1:]
    main(*args)
except CheckFailed as failure:
    print("FAIL: %s" % failure)
    sys.exit(1)

"""Weight curves as shape key animation in Blender: one F-curve per shape key named as a curve,
a key per sample (sample i at frame first_frame + i, as the take importer places a take's samples)."""

import bpy


def key_shape_keys(obj, curves, first_frame=1):
    """Keys `obj`'s shape keys from `curves` (a WeightCurves) by name, replacing the shape keys'
    action. Returns (keyed names, curve names without a shape key)."""
    keys = obj.data.shape_keys
    blocks = keys.key_blocks
    keyed = [n for n in curves.names if n in blocks and n != keys.reference_key.name]
    missing = [n for n in curves.names if n not in blocks]
    if not keyed:
        return keyed, missing
    keys.animation_data_create()
    action = bpy.data.actions.new(obj.name + " weights")
    keys.animation_data.action = action
    column = {n: c for c, n in enumerate(curves.names)}
    for name in keyed:
        c = column[name]
        curve = action.fcurves.new('key_blocks["%s"].value' % bpy.utils.escape_identifier(name))
        curve.keyframe_points.add(len(curves.rows))
        coords = []
        for i, row in enumerate(curves.rows):
            coords += [first_frame + i, row[c]]
        curve.keyframe_points.foreach_set("co", coords)
        curve.keyframe_points.foreach_set("interpolation", [1] * len(curves.rows))  # LINEAR
        curve.update()
    return keyed, missing

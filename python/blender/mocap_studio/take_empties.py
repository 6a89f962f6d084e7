"""A take as animated empties in Blender: one empty per marker under a root empty named after the
take, a location key per frame where the marker was seen, held (constant) through its gaps and
hidden there (hide_viewport/hide_render keys), and the sample states as a custom property."""

import bpy

from .take_source import METRES_PER_UNIT


def _runs(flags):
    """(first, last) index pairs of the runs of True in `flags`."""
    runs, start = [], None
    for i, flag in enumerate(flags + [False]):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            runs.append((start, i - 1))
            start = None
    return runs


def _key_location(action, samples, scale, first):
    """X, Y, Z F-curves with a key at every seen frame; the last key before a gap is constant."""
    seen = [i for i, p in enumerate(samples) if p is not None]
    for axis in range(3):
        curve = action.fcurves.new("location", index=axis)
        curve.keyframe_points.add(len(seen))
        coords = []
        for i in seen:
            coords += [first + i, samples[i][axis] * scale]
        curve.keyframe_points.foreach_set("co", coords)
        curve.keyframe_points.foreach_set("interpolation", [1] * len(seen))  # LINEAR
        for k, i in enumerate(seen[:-1]):
            if seen[k + 1] != i + 1:
                curve.keyframe_points[k].interpolation = "CONSTANT"
        curve.update()


def _key_hidden(action, samples, first):
    """hide_viewport and hide_render keys: hidden from each gap's first frame until it ends."""
    gaps = _runs([p is None for p in samples])
    if not gaps:
        return
    for path in ("hide_viewport", "hide_render"):
        curve = action.fcurves.new(path)
        keys = []
        for start, end in gaps:
            keys.append((first + start, 1.0))
            if end + 1 < len(samples):
                keys.append((first + end + 1, 0.0))
        if gaps[0][0] > 0:
            keys.insert(0, (first, 0.0))
        curve.keyframe_points.add(len(keys))
        curve.keyframe_points.foreach_set("co", [v for key in keys for v in key])
        for point in curve.keyframe_points:
            point.interpolation = "CONSTANT"


def build_take(context, take, name, first_frame=1):
    """Empties for `take` (a TakeSamples) in the current scene, take frame 0 at `first_frame`;
    sets the scene's frame range and rate. Returns the root empty."""
    scene = context.scene
    scale = METRES_PER_UNIT.get(take.units, 0.001) / scene.unit_settings.scale_length
    root = bpy.data.objects.new(name, None)
    context.collection.objects.link(root)
    root["mocap_units"] = take.units
    root["mocap_rate"] = take.rate
    for m, label in enumerate(take.labels):
        empty = bpy.data.objects.new(label, None)
        empty.empty_display_size = 0.004 / scene.unit_settings.scale_length
        empty.parent = root
        context.collection.objects.link(empty)
        samples = take.positions[m]
        if take.states is not None:
            empty["mocap_states"] = take.states[m]  # origin bits 0-1 (1 filled, 3 edited), 4 smoothed, 8 stabilized
        if not any(p is not None for p in samples):
            empty.hide_viewport = empty.hide_render = True
            continue
        empty.animation_data_create()
        action = bpy.data.actions.new(label)
        empty.animation_data.action = action
        _key_location(action, samples, scale, first_frame)
        _key_hidden(action, samples, first_frame)
    scene.frame_start = first_frame
    scene.frame_end = first_frame + max(take.frames - 1, 0)
    fps = max(int(round(take.rate)), 1)
    scene.render.fps = fps
    scene.render.fps_base = fps / take.rate if take.rate > 0 else 1.0
    return root

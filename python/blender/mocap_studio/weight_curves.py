"""Solved weight curves for Blender: `mocap solve`'s weight CSV (Frame,Time,<shape>,…) or a Live
Link Face CSV (Timecode,BlendShapeCount,<52 curves>,<9 rotations>), read as names and rows, and
taken through a retarget map by the `mocap` module (the core's applyRetargetMap) when one is given.
Plain Python: no bpy here."""

import csv


class WeightCurves:
    """names (one per column) and rows (one list of floats per sample, in file order)."""

    def __init__(self, names, rows):
        self.names = names
        self.rows = rows


def read_weight_curves(path):
    """The curves of a weight CSV or a Live Link Face CSV; ValueError naming the file and line
    for anything else."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError("%s is empty" % path)
    header = rows[0]
    if header[:2] == ["Frame", "Time"] or header[:2] == ["Timecode", "BlendShapeCount"]:
        names = header[2:]
    else:
        raise ValueError("%s: not a weight CSV (Frame,Time,…) nor a Live Link Face CSV (Timecode,BlendShapeCount,…)"
                         % path)
    values = []
    for line, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            raise ValueError("%s line %d: %d cells, the header has %d" % (path, line, len(row), len(header)))
        try:
            values.append([float(v) for v in row[2:]])
        except ValueError:
            raise ValueError("%s line %d: a weight is not a number" % (path, line)) from None
    return WeightCurves(names, values)


def retarget(curves, mocap, retarget_map):
    """`curves` through `retarget_map` (a shipped map's name or a map file) by the mocap module;
    RuntimeError when the module is missing (the map is applied by the core only)."""
    if mocap is None:
        raise RuntimeError("a retarget map needs the mocap Python module (set its folder in the add-on's preferences)")
    import numpy
    names, weights = mocap.retarget_weights(curves.names, numpy.array(curves.rows, dtype=float).reshape(
        len(curves.rows), len(curves.names)), retarget_map)
    return WeightCurves(list(names), weights.tolist())

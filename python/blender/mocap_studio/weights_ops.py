"""File ▸ Import ▸ Mocap Solved Weights (a weight CSV or Live Link Face CSV onto the active mesh's
shape keys by name, through a retarget map when one is given) and the Mocap sidebar panel that
solves a take onto the active mesh's shape keys (mocap.solve with a rig file and a binding)."""

import os

import bpy
from bpy.props import EnumProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

from . import shape_key_curves, take_source, weight_curves


def _module(context):
    """The mocap module (from the add-on's preferences' folder or MOCAP_PYTHON_PATH), or None."""
    addon = context.preferences.addons.get(__package__)
    folder = addon.preferences.module_path if addon else ""
    return take_source.import_mocap_module([bpy.path.abspath(folder)] if folder else [])


def _mesh_with_shape_keys(context):
    obj = context.active_object
    return obj if obj is not None and obj.type == "MESH" and obj.data.shape_keys is not None else None


def _key(operator, context, obj, curves, first_frame):
    keyed, missing = shape_key_curves.key_shape_keys(obj, curves, first_frame)
    if not keyed:
        operator.report({"ERROR"}, "no curve names a shape key of %s (curves: %s…); give a retarget map"
                        % (obj.name, ", ".join(curves.names[:4])))
        return {"CANCELLED"}
    context.scene.frame_start = first_frame
    context.scene.frame_end = first_frame + max(len(curves.rows) - 1, 0)
    note = ", %d curves without a shape key" % len(missing) if missing else ""
    operator.report({"INFO"}, "%d shape keys keyed over %d frames%s" % (len(keyed), len(curves.rows), note))
    return {"FINISHED"}


class IMPORT_ANIM_OT_mocap_weights(bpy.types.Operator, ImportHelper):
    """Key the active mesh's shape keys from solved weight curves (weight CSV or Live Link Face CSV)"""

    bl_idname = "import_anim.mocap_weights"
    bl_label = "Import Solved Weights"
    bl_options = {"REGISTER", "UNDO"}
    filter_glob: StringProperty(default="*.csv", options={"HIDDEN"})
    retarget_map: StringProperty(name="Retarget map", default="",
                                 description="A shipped map's name (arkit_to_ict, …) or a map file; empty: by name")
    first_frame: IntProperty(name="First frame", default=1, description="The frame of the first sample")

    @classmethod
    def poll(cls, context):
        return _mesh_with_shape_keys(context) is not None

    def execute(self, context):
        obj = _mesh_with_shape_keys(context)
        try:
            curves = weight_curves.read_weight_curves(self.filepath)
            if self.retarget_map:
                curves = weight_curves.retarget(curves, _module(context), self.retarget_map)
        except Exception as error:  # the reader's or the core's message is what the user needs
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        return _key(self, context, obj, curves, self.first_frame)


class MOCAP_OT_solve_shape_keys(bpy.types.Operator):
    """Solve the take to the rig's weights (mocap.solve) and key the active mesh's shape keys"""

    bl_idname = "mocap.solve_shape_keys"
    bl_label = "Solve onto Shape Keys"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return _mesh_with_shape_keys(context) is not None

    def execute(self, context):
        scene = context.scene
        mocap = _module(context)
        if mocap is None:
            self.report({"ERROR"}, "the solve needs the mocap Python module (set its folder in the add-on's preferences)")
            return {"CANCELLED"}
        try:
            paths = [bpy.path.abspath(p) for p in (scene.mocap_take, scene.mocap_rig, scene.mocap_binding)]
            for label, path in zip(("take", "rig", "binding"), paths):
                if not path or not os.path.isfile(path):
                    raise RuntimeError("the %s file '%s' does not exist" % (label, path))
            take = mocap.read(paths[0])
            rig = mocap.load_rig(paths[1])
            result = mocap.solve(take, rig, mocap.read_binding(paths[2], rig), method=scene.mocap_method)
        except Exception as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        curves = weight_curves.WeightCurves(list(result["names"]), result["weights"].tolist())
        return _key(self, context, _mesh_with_shape_keys(context), curves, 1)


class VIEW3D_PT_mocap_solve(bpy.types.Panel):
    bl_label = "Mocap Solve"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Mocap"

    def draw(self, context):
        scene = context.scene
        for prop in ("mocap_take", "mocap_rig", "mocap_binding", "mocap_method"):
            self.layout.prop(scene, prop)
        self.layout.operator(MOCAP_OT_solve_shape_keys.bl_idname)
        self.layout.operator(IMPORT_ANIM_OT_mocap_weights.bl_idname)


_scene_properties = {
    "mocap_take": StringProperty(name="Take", subtype="FILE_PATH", description="The take (.c3d, .trc) to solve"),
    "mocap_rig": StringProperty(name="Rig", subtype="FILE_PATH",
                                description="The rig file the mesh was made from (.glb, or an OBJ neutral)"),
    "mocap_binding": StringProperty(name="Binding", subtype="FILE_PATH",
                                    description="The take's markers bound to the rig (mocap bind's JSON)"),
    "mocap_method": EnumProperty(name="Method", default="temporal",
                                 items=[(m, m, "mocap solve --method " + m) for m in ("temporal", "bvls", "ridge")]),
}

classes = (IMPORT_ANIM_OT_mocap_weights, MOCAP_OT_solve_shape_keys, VIEW3D_PT_mocap_solve)


def register_properties():
    for name, prop in _scene_properties.items():
        setattr(bpy.types.Scene, name, prop)


def unregister_properties():
    for name in _scene_properties:
        delattr(bpy.types.Scene, name)

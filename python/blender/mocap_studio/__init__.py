"""Mocap Studio for Blender: File ▸ Import ▸ Mocap Take (.c3d, .trc) as animated empties, with
gaps as hidden keys and each sample's state (measured, filled, edited) as a custom property;
File ▸ Import ▸ Mocap Solved Weights (weight or Live Link Face CSV onto the active mesh's shape
keys) and the 3D view's Mocap tab, which solves a take onto them. Uses the `mocap` Python module
when Blender's Python can import it, else the `mocap` command line (takes only). Enabling it also
lets Debian's Blender 3.4 import glTF rigs again (numpy_compat.py)."""

bl_info = {
    "name": "Mocap Studio",
    "author": "Mocap Studio",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > Mocap Take / Mocap Solved Weights; 3D View > Sidebar > Mocap",
    "description": "Import motion capture takes cleaned with Mocap Studio",
    "category": "Import-Export",
}

import os

import bpy
from bpy.props import StringProperty
from bpy_extras.io_utils import ImportHelper

from . import numpy_compat, take_empties, take_source, weights_ops


class MocapStudioPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    module_path: StringProperty(name="mocap module folder", subtype="DIR_PATH",
                                description="Folder holding the mocap Python module (build/python)")
    cli_path: StringProperty(name="mocap command", subtype="FILE_PATH",
                             description="The mocap executable, used when the module cannot be imported")

    def draw(self, context):
        self.layout.prop(self, "module_path")
        self.layout.prop(self, "cli_path")


def _preferences(context):
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon else None


class IMPORT_SCENE_OT_mocap_take(bpy.types.Operator, ImportHelper):
    """Import a motion capture take as animated empties"""

    bl_idname = "import_scene.mocap_take"
    bl_label = "Import Mocap Take"
    bl_options = {"REGISTER", "UNDO"}
    filter_glob: StringProperty(default="*.c3d;*.trc", options={"HIDDEN"})

    def execute(self, context):
        prefs = _preferences(context)
        paths = [bpy.path.abspath(prefs.module_path)] if prefs and prefs.module_path else []
        cli = bpy.path.abspath(prefs.cli_path) if prefs and prefs.cli_path else ""
        try:
            take = take_source.read_take(self.filepath, paths, cli)
        except Exception as error:  # the reader's message is what the user needs
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        name = os.path.splitext(os.path.basename(self.filepath))[0]
        take_empties.build_take(context, take, name)
        self.report({"INFO"}, "%d markers, %d frames at %g Hz" % (len(take.labels), take.frames, take.rate))
        return {"FINISHED"}


def _menu(self, context):
    self.layout.operator(IMPORT_SCENE_OT_mocap_take.bl_idname, text="Mocap Take (.c3d, .trc)")
    self.layout.operator(weights_ops.IMPORT_ANIM_OT_mocap_weights.bl_idname, text="Mocap Solved Weights (.csv)")


_classes = (MocapStudioPreferences, IMPORT_SCENE_OT_mocap_take) + weights_ops.classes


def register():
    numpy_compat.restore_numpy_bool()  # for Debian's Blender 3.4 glTF importer (numpy_compat.py)
    for cls in _classes:
        bpy.utils.register_class(cls)
    weights_ops.register_properties()
    bpy.types.TOPBAR_MT_file_import.append(_menu)


def unregister():
    bpy.types.TOPBAR_MT_file_import.remove(_menu)
    weights_ops.unregister_properties()
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)

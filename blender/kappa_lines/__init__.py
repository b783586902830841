"""kappa lines: kappa's line drawings (occluding and suggestive contours, ridges, apparent ridges,
...) of the selected meshes as Grease Pencil strokes. docs/blender.md tells how to install it."""

bl_info = {
    "name": "kappa lines",
    "author": "the kappa project",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D View > Sidebar > kappa; Grease Pencil object > Data properties",
    "description": "Suggestive contours and every kappa line as Grease Pencil strokes",
    "category": "Object",
}

import bpy

from . import kappa_module, operators, panels, settings


def _module_folder_changed(prefs, context):
    register_settings(prefs.module_folder)


class KappaLinesPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    module_folder: bpy.props.StringProperty(
        name="kappa module folder", subtype="DIR_PATH", update=_module_folder_changed,
        description="folder holding kappa's Python module (kappa*.so), such as kappa's build/python; "
                    "leave empty when it is installed")

    def draw(self, context):
        self.layout.prop(self, "module_folder")
        kappa = kappa_module.module()
        if kappa is None:
            self.layout.label(text=kappa_module.problem(), icon="ERROR")
        else:
            self.layout.label(text=f"kappa module: {kappa.__file__}", icon="CHECKMARK")


_settings_class = None


def register_settings(folder=""):
    """scene.kappa_lines, once kappa's module (which holds the settings table) is found."""
    global _settings_class
    kappa = kappa_module.load(folder)
    if kappa is None or _settings_class is not None:
        return
    _settings_class = settings.make_settings_class(kappa)
    bpy.utils.register_class(_settings_class)
    bpy.types.Scene.kappa_lines = bpy.props.PointerProperty(type=_settings_class)


def register():
    bpy.utils.register_class(KappaLinesPreferences)
    for cls in operators.classes + panels.classes:
        bpy.utils.register_class(cls)
    prefs = bpy.context.preferences.addons.get(__package__)
    register_settings(prefs.preferences.module_folder if prefs else "")


def unregister():
    global _settings_class
    if _settings_class is not None:
        del bpy.types.Scene.kappa_lines
        bpy.utils.unregister_class(_settings_class)
        _settings_class = None
    for cls in reversed(operators.classes + panels.classes):
        bpy.utils.unregister_class(cls)
    bpy.utils.unregister_class(KappaLinesPreferences)

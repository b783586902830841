"""The kappa lines panel, in the 3D view's sidebar (tab 'kappa') and in the Grease Pencil object's
data properties: the line types in kappa's groups, each with its threshold, then detail, width and
fading, and the operators."""
import bpy

from . import kappa_module, settings


def draw_settings(layout, context):
    kappa = kappa_module.module()
    props = getattr(context.scene, "kappa_lines", None)
    if kappa is None or props is None:
        layout.label(text="kappa's Python module was not found", icon="ERROR")
        layout.label(text="set its folder in the add-on's preferences")
        return
    col = layout.column(align=True)
    col.operator("kappa.draw_lines", icon="GREASEPENCIL")
    row = col.row(align=True)
    row.operator("kappa.bake_frames", text="Bake frames", icon="RENDER_ANIMATION")
    row.operator("kappa.export_svg", text="Export SVG", icon="EXPORT")
    for group in kappa.line_groups():
        box = layout.box()
        box.label(text=group["title"])
        for line in group["lines"]:
            row = box.split(factor=0.6, align=True)  # room for the labels in a narrow sidebar
            row.prop(props, settings.line_property(line["kind"]))
            if line["setting"]:
                sub = row.row(align=True)
                sub.active = getattr(props, settings.line_property(line["kind"]))
                sub.prop(props, line["setting"], text="")
    col = layout.column()
    row = col.row(align=True)
    row.prop(props, "detail_on", text="")
    sub = row.row(align=True)
    sub.active = props.detail_on
    sub.prop(props, "detail")
    for name in ("line_width", "fade", "width_by_strength", "simplify", "min_stroke", "line_color",
                 "hidden_lines", "pull", "time_limit"):
        col.prop(props, name)
    box = layout.box()
    box.prop(props, "hatching")
    sub = box.row()
    sub.active = props.hatching != "none"
    sub.prop(props, "hatch_spacing")


class KAPPA_PT_sidebar(bpy.types.Panel):
    bl_label = "kappa lines"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "kappa"

    def draw(self, context):
        draw_settings(self.layout, context)


class KAPPA_PT_grease_pencil(bpy.types.Panel):
    bl_label = "kappa lines"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "data"

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.type == "GPENCIL"

    def draw(self, context):
        draw_settings(self.layout, context)


classes = (KAPPA_PT_sidebar, KAPPA_PT_grease_pencil)

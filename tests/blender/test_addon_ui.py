"""The add-on's bad cases (one line in Blender's report, no traceback), export_svg through kappa's
writer, and scene.kappa_lines built from kappa's settings table."""
import math
import os
import sys
import tempfile

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_test as bt  # noqa: E402


def one_line(message, *words):
    assert "\n" not in message.strip() and "Traceback" not in message, message
    for word in words:
        assert word in message, (word, message)
    print(f"  {message.strip()}")


def test_no_mesh_selected():
    scene = bpy.context.scene
    bt.suzanne(scene)
    bt.add_camera(scene, (0, -4, 0), (0, 0, 0))
    bt.select_only()
    one_line(bt.draw_error(bpy.ops.kappa.draw_lines), "no mesh selected")
    one_line(bt.draw_error(bpy.ops.kappa.bake_frames, frame_start=1, frame_end=2), "no mesh selected")
    assert "kappa lines" not in bpy.data.objects


def test_object_with_no_faces():
    scene = bpy.context.scene
    monkey = bt.suzanne(scene)
    mesh = bpy.data.meshes.new("points")
    mesh.from_pydata([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1), (1, 2)], [])
    wire = bpy.data.objects.new("wire", mesh)
    scene.collection.objects.link(wire)
    bt.add_camera(scene, (0, -4, 0), (0, 0, 0))
    bt.select_only(monkey, wire)
    one_line(bt.draw_error(bpy.ops.kappa.draw_lines), "'wire' has no faces")


def test_camera_inside_the_model():
    scene = bpy.context.scene
    bpy.ops.mesh.primitive_uv_sphere_add(radius=2)
    sphere = bpy.context.active_object
    bt.add_camera(scene, (0.3, 0.2, 0.1), (0, 1, 0))
    bt.select_only(sphere)
    one_line(bt.draw_error(bpy.ops.kappa.draw_lines), "camera is inside 'Sphere'")
    # Outside, the same sphere draws.
    bt.aim(scene.camera, (0, -8, 0), (0, 0, 0))
    assert bpy.ops.kappa.draw_lines() == {"FINISHED"}


def test_mesh_too_large_for_the_time_limit():
    scene = bpy.context.scene
    monkey = bt.suzanne(scene, levels=3)  # 62,976 triangles
    bt.add_camera(scene, (0, -4, 0), (0, 0, 0))
    bt.select_only(monkey)
    scene.kappa_lines.time_limit = 1.0  # the least Blender allows is 0.5 s; the estimate is 1.05 s
    one_line(bt.draw_error(bpy.ops.kappa.draw_lines), "62,976 faces at 480x360 pixels", "time limit of 1 s")
    scene.kappa_lines.time_limit = 2.0
    # The image's size counts: at 7680x4320 (33 megapixels) the estimate is 6 s, 16 s with hatching.
    scene.render.resolution_x, scene.render.resolution_y = 7680, 4320
    one_line(bt.draw_error(bpy.ops.kappa.draw_lines), "62,976 faces at 7680x4320 pixels", "about 6 s")
    scene.kappa_lines.time_limit = 10.0
    scene.kappa_lines.hatching = "cross"
    one_line(bt.draw_error(bpy.ops.kappa.draw_lines), "at 7680x4320 pixels", "about 16 s")
    scene.kappa_lines.hatching = "none"
    scene.kappa_lines.time_limit = 2.0
    scene.render.resolution_x, scene.render.resolution_y = 480, 360
    assert bpy.ops.kappa.draw_lines() == {"FINISHED"}


def test_no_camera_and_no_3d_view():
    scene = bpy.context.scene
    monkey = bt.suzanne(scene)
    bt.select_only(monkey)
    one_line(bt.draw_error(bpy.ops.kappa.draw_lines), "no camera")


def test_export_svg_writes_kappas_layers():
    scene = bpy.context.scene
    monkey = bt.suzanne(scene)
    bt.add_camera(scene, (2, -3, 1), (0, 0, 0))
    bt.select_only(monkey)
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "monkey.svg")
        assert bpy.ops.kappa.export_svg(filepath=path) == {"FINISHED"}
        svg = open(path).read()
        assert svg.startswith("<?xml") and 'width="480"' in svg and 'height="360"' in svg
        for layer in ("contours", "suggestive"):
            assert f'inkscape:label="{layer}"' in svg, layer
        assert "<image" not in svg  # lines only, no picture of the surface under them
        one_line(bt.draw_error(bpy.ops.kappa.export_svg, filepath=os.path.join(folder, "monkey.png")), "must end in .svg")


def test_settings_come_from_kappas_table():
    props = bpy.context.scene.kappa_lines
    table = {s["name"]: s for s in bt.kappa.settings()}
    for name in ("detail", "line_width", "sc_threshold", "rv_threshold", "isophotes"):
        rna = props.bl_rna.properties[name]
        assert math.isclose(getattr(props, name), table[name]["default"], rel_tol=1e-6), name
        assert rna.description == table[name]["help"] and rna.name == table[name]["label"], name
        assert rna.soft_max == table[name]["max"], name
    assert props.fade == table["fade"]["default"] and props.detail_on
    on = {line["kind"] for g in bt.kappa.line_groups() for line in g["lines"]
          if getattr(props, "line_" + line["kind"].replace("-", "_"))}
    assert on == set(table["lines"]["default"])
    # A choice: hatching's words, default and help.
    rna = props.bl_rna.properties["hatching"]
    assert [item.identifier for item in rna.enum_items] == table["hatching"]["choices"]
    assert props.hatching == table["hatching"]["default"] and rna.description == table["hatching"]["help"]
    assert props.hidden_lines == table["hidden_lines"]["default"]


class Layout:
    """Stands in for bpy.types.UILayout: records what the panel draws."""

    def __init__(self, drawn):
        self.drawn, self.active = drawn, True

    def column(self, **_):
        return Layout(self.drawn)

    row = box = split = column

    def label(self, text="", **_):
        self.drawn.append(("label", text))

    def prop(self, data, name, **_):
        assert name in data.bl_rna.properties, name
        self.drawn.append(("prop", name))

    def operator(self, idname, **_):
        module, name = idname.split(".")
        assert hasattr(getattr(bpy.ops, module), name), idname
        self.drawn.append(("operator", idname))


def test_panel_draws_every_setting_and_operator():
    from kappa_lines import panels
    drawn = []
    panels.draw_settings(Layout(drawn), bpy.context)
    props = {name for kind, name in drawn if kind == "prop"}
    operators = {name for kind, name in drawn if kind == "operator"}
    assert operators == {"kappa.draw_lines", "kappa.bake_frames", "kappa.export_svg"}
    rna = set(bpy.context.scene.kappa_lines.bl_rna.properties.keys()) - {"rna_type", "name"}  # (every PropertyGroup's)
    assert props == rna, rna ^ props  # every setting has its widget, and no widget lacks its setting
    assert "suggestive highlights" in {bpy.context.scene.kappa_lines.bl_rna.properties[p].name for p in props}


bt.run(globals())

"""The add-on in Blender's window (under Xvfb; tests/CMakeLists.txt). draw_lines invoked in a 3D view
of a scene without camera draws that view: its strokes, projected by the view's own matrix, agree
with kappa.render of the view. bake_frames invoked from the 3D view bakes a frame at a time while
Blender keeps drawing, with its progress in the status bar, and Esc cancels it, keeping the frames
drawn so far and going back to the frame the user was on. Run as
    xvfb-run -a blender --factory-startup --window-geometry 0 0 640 480 --enable-event-simulate \
        --python-exit-code 1 --python gui_bake.py"""
import os
import sys
import traceback

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_test as bt  # noqa: E402  (registers the add-on)

state = {"ticks": 0, "frames_seen": [], "cancelled_at": None, "statuses": set()}
FIRST, LAST = 1, 60


def window_and_view():
    window = bpy.context.window_manager.windows[0]
    return window, next(a for a in window.screen.areas if a.type == "VIEW_3D")


def frames_baked():
    obj = bpy.data.objects.get("kappa lines")
    return sorted(f.frame_number for f in obj.data.layers["contours"].frames) if obj else []


def finish(ok, message):
    print(("PASS " if ok else "FAIL ") + message, flush=True)
    window, _ = window_and_view()
    with bpy.context.temp_override(window=window):
        bpy.ops.wm.quit_blender()
    os._exit(0 if ok else 1)  # quit_blender saves no exit status


def start():
    try:
        bpy.ops.mesh.primitive_monkey_add()
        monkey = bpy.context.active_object
        bt.select_only(monkey)
        bpy.context.scene.frame_set(7)
        state["camera"], bpy.context.scene.camera = bpy.context.scene.camera, None
        window, area = window_and_view()
        region = next(r for r in area.regions if r.type == "WINDOW")
        r3d = area.spaces.active.region_3d
        r3d.view_perspective = "PERSP"
        r3d.view_location, r3d.view_distance = (0, 0, 0), 5
        r3d.update()  # the view matrices now, not at the next redraw
        with bpy.context.temp_override(window=window, area=area, region=region):
            result = bpy.ops.kappa.draw_lines("INVOKE_DEFAULT")
        assert result == {"RUNNING_MODAL"}, result
    except Exception:
        traceback.print_exc()
        finish(False, "draw_lines did not start")
    bpy.app.timers.register(check_viewport_lines, first_interval=0.1)


def check_viewport_lines():
    if "kappa lines" not in bpy.data.objects:
        state["ticks"] += 1
        if state["ticks"] > 300:
            finish(False, "no kappa lines after 30 s")
        return 0.1
    try:
        window, area = window_and_view()
        region = next(r for r in area.regions if r.type == "WINDOW")
        r3d = area.spaces.active.region_3d
        scene = bpy.context.scene
        strokes = [s for layer in bt.gp_strokes().values() for s in layer]
        size = (region.width, region.height)
        a = bt.stroke_ink(scene, strokes, project=lambda p: bt.region_pixels(region, r3d, p), size=size)
        from kappa_lines import drawing, scene_view, settings
        mesh = scene_view.SceneMesh(bpy.context)
        view = scene_view.viewport_view(region, r3d)
        # On kappa's thread, as the add-on draws: Blender's thread holds Blender's GL context.
        image = drawing.in_worker(bt.kappa.render, mesh.V, mesh.F, camera=view.camera, size=view.size,
                                  shading="none", **settings.keywords(scene.kappa_lines, bt.kappa)).result()
        b = bt.render_ink(image)
        within = bt.kappa.ink_agreement(a, image, 2)
        print(f"3D view {size}: ink within 2 px {within[0]:.3f} and {within[1]:.3f} ({a.sum()} and {b.sum()} px)",
              flush=True)
        assert a.sum() > 300 and min(within) >= 0.95, within
        scene.camera = state["camera"]
        scene.render.resolution_x, scene.render.resolution_y = 480, 360  # kappa's image: small, quick
        for layer in bpy.data.objects["kappa lines"].data.layers:
            layer.clear()
        with bpy.context.temp_override(window=window, area=area):
            result = bpy.ops.kappa.bake_frames("INVOKE_DEFAULT", frame_start=FIRST, frame_end=LAST)
        assert result == {"RUNNING_MODAL"}, result
    except Exception:
        traceback.print_exc()
        finish(False, "viewport lines or bake start")
    state["ticks"] = 0
    bpy.app.timers.register(watch, first_interval=0.1)
    return None


def watch():
    state["ticks"] += 1
    baked = frames_baked()
    window, _ = window_and_view()
    if state["cancelled_at"] is None and len(baked) >= 2:
        # Blender kept running while kappa drew: frames came one by one, the scene stepping through them.
        state["cancelled_at"] = baked
        window.event_simulate(type="ESC", value="PRESS")
        window.event_simulate(type="ESC", value="RELEASE")
        return 0.5
    if state["cancelled_at"] is not None:
        kept = frames_baked()
        ok = (kept == list(range(FIRST, FIRST + len(kept))) and len(kept) < LAST and
              bpy.context.scene.frame_current == 7)
        finish(ok, f"Esc after frames {state['cancelled_at']}: kept {kept}, back on frame "
                   f"{bpy.context.scene.frame_current} (ticks while baking: {state['ticks']})")
        return None
    if state["ticks"] > 600:
        finish(False, f"no 2 frames after 60 s: {baked}")
        return None
    return 0.1


bpy.app.timers.register(start, first_interval=1.0)

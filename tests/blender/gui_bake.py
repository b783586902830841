"""bake_frames in Blender's window (under Xvfb; tests/CMakeLists.txt): invoked from the 3D view it
bakes a frame at a time while Blender keeps drawing, with its progress in the status bar, and Esc
cancels it, keeping the frames drawn so far and going back to the frame the user was on. Run as
    xvfb-run -a blender --factory-startup --enable-event-simulate --python-exit-code 1 --python gui_bake.py"""
import os
import sys
import traceback

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../blender"))
import kappa_lines  # noqa: E402
from kappa_lines import kappa_module  # noqa: E402

kappa_module.load(os.environ.get("KAPPA_PYTHON_DIR", ""))
kappa_lines.register()

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
        monkey.modifiers.new("subdivision", "SUBSURF").levels = 1
        for obj in bpy.context.view_layer.objects:
            obj.select_set(obj == monkey)
        bpy.context.scene.frame_set(7)
        window, area = window_and_view()
        with bpy.context.temp_override(window=window, area=area):
            result = bpy.ops.kappa.bake_frames("INVOKE_DEFAULT", frame_start=FIRST, frame_end=LAST)
        assert result == {"RUNNING_MODAL"}, result
    except Exception:
        traceback.print_exc()
        finish(False, "bake did not start")
    bpy.app.timers.register(watch, first_interval=0.1)


def watch():
    state["ticks"] += 1
    baked = frames_baked()
    window, _ = window_and_view()
    if state["cancelled_at"] is None and len(baked) >= 3:
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
        finish(False, f"no 3 frames after 60 s: {baked}")
        return None
    return 0.1


bpy.app.timers.register(start, first_interval=1.0)

"""The add-on's operators: bpy.ops.kappa.draw_lines(), bpy.ops.kappa.bake_frames(frame_start=...,
frame_end=...), bpy.ops.kappa.export_svg(filepath=...). A problem ends an operator with one line in
Blender's report (scripts see it as the RuntimeError of the operator call), never a traceback."""
import time

import bpy

from . import drawing
from .drawing import DrawError


class KAPPA_OT_draw_lines(bpy.types.Operator):
    """Draw the selected meshes' kappa lines, seen from the scene camera (or this 3D view), into the
    Grease Pencil object 'kappa lines' at the current frame"""
    bl_idname = "kappa.draw_lines"
    bl_label = "Draw kappa lines"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        """Blender waits (scripts, background mode)."""
        try:
            count, seconds = drawing.draw_now(context, context.scene.frame_current)
        except DrawError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, f"kappa lines: {count} strokes in {seconds:.2f} s")
        return {"FINISHED"}

    def invoke(self, context, event):
        """In the UI: kappa draws while Blender keeps drawing; Esc drops the result."""
        try:
            self._job = drawing.Job(context, context.scene.frame_current)
            self._job.start()
        except DrawError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self._start = time.perf_counter()
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.05, window=context.window)
        wm.modal_handler_add(self)
        context.workspace.status_text_set("kappa lines: drawing (Esc cancels)")
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type not in ("TIMER", "ESC"):
            return {"PASS_THROUGH"}
        if event.type == "TIMER" and not self._job.done():
            return {"RUNNING_MODAL"}
        context.window_manager.event_timer_remove(self._timer)
        context.workspace.status_text_set(None)
        if event.type == "ESC":
            self.report({"WARNING"}, "kappa lines: cancelled (kappa finishes its frame, which is dropped)")
            return {"CANCELLED"}
        try:
            count = self._job.finish(context.scene)
        except DrawError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, f"kappa lines: {count} strokes in {time.perf_counter() - self._start:.2f} s")
        return {"FINISHED"}


class KAPPA_OT_bake_frames(bpy.types.Operator):
    """Draw kappa lines on every frame of a range into Grease Pencil frames (moving cameras and
    objects); Esc cancels, keeping the frames drawn so far"""
    bl_idname = "kappa.bake_frames"
    bl_label = "Bake kappa lines"
    bl_options = {"REGISTER", "UNDO"}

    frame_start: bpy.props.IntProperty(name="Start", default=1, description="first frame drawn")
    frame_end: bpy.props.IntProperty(name="End", default=250, description="last frame drawn")

    def _check_range(self):
        if self.frame_end < self.frame_start:
            raise DrawError(f"kappa lines: the frame range {self.frame_start}-{self.frame_end} is empty")

    def execute(self, context):
        """All frames at once (scripts, background mode): Blender waits."""
        scene = context.scene
        current = scene.frame_current
        try:
            self._check_range()
            total = 0
            for frame in range(self.frame_start, self.frame_end + 1):
                scene.frame_set(frame)
                total += drawing.draw_now(context, frame)[0]
        except DrawError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        finally:
            scene.frame_set(current)
        self.report({"INFO"}, f"kappa lines: {self.frame_end - self.frame_start + 1} frames baked, {total} strokes")
        return {"FINISHED"}

    def invoke(self, context, event):
        """In the UI: a frame at a time while Blender keeps drawing, with progress; Esc cancels."""
        scene = context.scene
        if not self.properties.is_property_set("frame_start"):
            self.frame_start = scene.frame_start
        if not self.properties.is_property_set("frame_end"):
            self.frame_end = scene.frame_end
        try:
            self._check_range()
        except DrawError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self._return_to = scene.frame_current
        self._frame = self.frame_start
        self._job = None
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.05, window=context.window)
        wm.progress_begin(self.frame_start, self.frame_end)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _end(self, context, result, level, message):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)
        if self._job is not None:
            self._job.future.result()  # let kappa finish before Blender moves on
        context.scene.frame_set(self._return_to)
        self.report({level}, message)
        return {result}

    def modal(self, context, event):
        scene = context.scene
        if event.type == "ESC":
            return self._end(context, "CANCELLED", "WARNING",
                             f"kappa lines: bake cancelled, frames {self.frame_start}-{self._frame - 1} kept")
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        try:
            if self._job is None:
                scene.frame_set(self._frame)
                self._job = drawing.Job(context, self._frame)
                self._job.start()
            elif self._job.done():
                job, self._job = self._job, None
                job.finish(scene)
                context.window_manager.progress_update(self._frame)
                context.workspace.status_text_set(
                    f"kappa lines: frame {self._frame} of {self.frame_start}-{self.frame_end} (Esc cancels)")
                self._frame += 1
                if self._frame > self.frame_end:
                    return self._end(context, "FINISHED", "INFO",
                                     f"kappa lines: frames {self.frame_start}-{self.frame_end} baked")
        except DrawError as e:
            self._job = None
            return self._end(context, "CANCELLED", "ERROR", f"{e} (frame {self._frame})")
        return {"RUNNING_MODAL"}


class KAPPA_OT_export_svg(bpy.types.Operator):
    """Write the selected meshes' kappa lines, seen from the scene camera, as SVG through kappa's own
    writer (an Inkscape layer per line type)"""
    bl_idname = "kappa.export_svg"
    bl_label = "Export kappa SVG"

    filepath: bpy.props.StringProperty(name="File", subtype="FILE_PATH", default="kappa-lines.svg")
    filter_glob: bpy.props.StringProperty(default="*.svg", options={"HIDDEN"})

    def execute(self, context):
        try:
            if not self.filepath.lower().endswith(".svg"):
                raise DrawError(f"kappa lines: {self.filepath}: the SVG file's name must end in .svg")
            scene = drawing.Scene(context)
            path = bpy.path.abspath(self.filepath)
            # Lines alone: the surface is left out of the SVG (shading none: no picture under the strokes).
            drawing.result_of(drawing.in_worker(scene.kappa.write, scene.mesh.V, scene.mesh.F, path,
                                                camera=scene.view.camera, size=scene.view.size, shading="none",
                                                **scene.keywords))
        except DrawError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, f"kappa lines: wrote {path}")
        return {"FINISHED"}

    def invoke(self, context, event):
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}


classes = (KAPPA_OT_draw_lines, KAPPA_OT_bake_frames, KAPPA_OT_export_svg)

"""One frame of kappa lines: the scene read on Blender's thread (Job.prepare), kappa.strokes run on a
worker thread (kappa's own headless GL context is made current there, never on the thread that holds
Blender's), the Grease Pencil frame written back on Blender's thread (Job.finish)."""
import concurrent.futures
import time

from . import grease_pencil, kappa_module, scene_view, settings
from .scene_view import DrawError

# kappa's time per frame with software GL (llvmpipe), measured with kappa.strokes on a shared 2-core
# machine: about SECONDS_START, plus a face every 1 / FACES_PER_SECOND (at 1920x1080: bunny 69k faces
# 1.34 s, dragon 100k 1.53 s, bunny-1M 1.11M 6.8 s), plus SECONDS_PER_MEGAPIXEL of the image (spot,
# 6k faces: 0.15 s at 480x270, 0.45 s at 1920x1080, 1.24 s at 3840x2160), more with hatching (its
# streamlines are traced over the image: spot 0.20, 1.31, 3.41 s). GPUs are faster; the estimate
# only has to keep meshes and images that would take minutes from freezing Blender.
SECONDS_START = 0.7
FACES_PER_SECOND = 190_000
SECONDS_PER_MEGAPIXEL = 0.15
HATCHING_SECONDS_PER_MEGAPIXEL = 0.3  # added when hatching is on

_worker = concurrent.futures.ThreadPoolExecutor(max_workers=1, thread_name_prefix="kappa")


def kappa_or_error():
    kappa = kappa_module.module()
    if kappa is None:
        raise DrawError("kappa lines: " + kappa_module.problem())
    return kappa


def estimated_seconds(face_count, size, hatching):
    """kappa's seconds a frame for this many faces at an image size (w, h), with or without hatching."""
    per_megapixel = SECONDS_PER_MEGAPIXEL + (HATCHING_SECONDS_PER_MEGAPIXEL if hatching else 0)
    return SECONDS_START + face_count / FACES_PER_SECOND + size[0] * size[1] / 1e6 * per_megapixel


def in_worker(function, *args, **keywords):
    """function(*args, **keywords) on kappa's thread: a concurrent.futures.Future."""
    return _worker.submit(function, *args, **keywords)


def result_of(future):
    """The future's result; kappa's exceptions (MeshError, ValueError, RuntimeError) as DrawError."""
    try:
        return future.result()
    except Exception as e:
        raise DrawError(f"kappa lines: {e}") from None


class Scene:
    """What a kappa call needs from the scene, checked: the module, the view, the selected meshes
    (not too many faces for the time limit, the camera outside them) and the settings' keywords."""

    def __init__(self, context):
        self.kappa = kappa_or_error()
        self.props = context.scene.kappa_lines
        self.view = scene_view.current_view(context)
        self.mesh = scene_view.SceneMesh(context)
        seconds = estimated_seconds(self.mesh.face_count, self.view.size, self.props.hatching != "none")
        if seconds > self.props.time_limit:
            w, h = self.view.size
            raise DrawError(f"kappa lines: {self.mesh.face_count:,} faces at {w}x{h} pixels would take about "
                            f"{seconds:.2g} s a frame, "
                            f"more than the time limit of {self.props.time_limit:g} s: raise it in the panel, decimate "
                            "or lower the resolution")
        self.mesh.check_outside(self.view.eye)
        self.keywords = settings.keywords(self.props, self.kappa)


class Job(Scene):
    """One frame: made on Blender's thread, start() hands kappa's part to the worker, finish()
    writes the strokes."""

    def __init__(self, context, frame_number):
        super().__init__(context)
        self.frame_number = frame_number
        self.future = None

    def start(self):
        k = dict(self.keywords)
        k.pop("line_color")  # the Grease Pencil material's colour
        self.future = in_worker(self.kappa.strokes, self.mesh.V, self.mesh.F, camera=self.view.camera,
                                size=self.view.size, space="model", **k)

    def done(self):
        return self.future.done()

    def finish(self, scene):
        """Writes the frame; returns the number of strokes."""
        strokes = result_of(self.future)
        obj = grease_pencil.lines_object(scene)
        material = grease_pencil.line_material(obj, tuple(self.props.line_color))
        # The chosen layers, and kappa's other layers already there (emptied: lines no longer chosen).
        layers = settings.layer_names(self.props, self.kappa)
        layers += [name for name in settings.layer_names(self.props, self.kappa, chosen=False)
                   if name in obj.data.layers and name not in layers]
        grease_pencil.write_frame(obj, self.frame_number, strokes, self.view.eye, layers, self.props.pull,
                                  self.props.line_width, self.props.width_by_strength, material)
        return len(strokes)


def draw_now(context, frame_number):
    """Draws one frame and waits for it; returns (strokes, seconds)."""
    start = time.perf_counter()
    job = Job(context, frame_number)
    job.start()
    count = job.finish(context.scene)
    return count, time.perf_counter() - start

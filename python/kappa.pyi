"""Type stubs of the kappa module (python/*.cpp): curvature and line drawings of triangle meshes."""
from os import PathLike
from typing import Any, Mapping, Sequence, TypedDict, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, PathLike[str]]
_Float32 = npt.NDArray[np.float32]

class MeshError(ValueError):
    """A mesh file or (V, F) arrays that cannot be used: "PATH: problem", as the command line says."""

class ContextError(RuntimeError):
    """No headless OpenGL context could be made (EGL)."""

def load_mesh(path: _Path) -> tuple[_Float32, npt.NDArray[np.uint32]]:
    """(V float32 (N, 3), F uint32 (M, 3)) from .ply .obj .off .stl .gltf .glb; raises MeshError."""

class Fields(TypedDict):
    normals: _Float32  # (N, 3)
    k1: _Float32  # (N,)
    k2: _Float32  # (N,)
    d1: _Float32  # (N, 3)
    d2: _Float32  # (N, 3)
    C: _Float32  # (N, 4): a, b, c, d
    flags: npt.NDArray[np.uint8]  # (N,)
    smoothing: tuple[float, float, float]  # widths used: normals, curvature, dcurv

def curvature(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    smooth: Union[None, str, Sequence[float]] = None,
    estimator: str = "rusinkiewicz",
    threads: int | None = None,
    *,
    smooth_normals: float = ...,
    smooth_curvature: float = ...,
    smooth_dcurv: float = ...,
) -> Fields:
    """Per-vertex fields exactly as `kappa curvature` writes them."""

# camera: None (the default view) or a dict with view=(az, el), eye, target, up, fov, xf.
_Camera = Union[None, Mapping[str, Any]]

def render(V: npt.ArrayLike, F: npt.ArrayLike, *, camera: _Camera = None, **settings: Any) -> npt.NDArray[np.uint8]:
    """(height, width, 4) RGBA image, as `kappa render`; settings are its options with '-' spelled '_'."""

class Stroke(TypedDict):
    type: str  # 'contours', 'suggestive', ..., 'hatching'
    hidden: bool
    points: _Float32  # (n, 2) image pixels, y down
    opacity: _Float32  # (n,)
    strength: _Float32  # (n,) or empty
    width: float  # pixels; 0: the drawing's line width
    model_points: _Float32  # (n, 3) on the surface, in V's coordinates; only with space='model'

def strokes(
    V: npt.ArrayLike, F: npt.ArrayLike, *, camera: _Camera = None, space: str = "image", **settings: Any
) -> list[Stroke]:
    """The visible lines of a view as polylines, as `kappa render -o out.svg` writes them;
    space='model' adds each point's place on the surface (model_points)."""

def write(V: npt.ArrayLike, F: npt.ArrayLike, path: _Path, *, camera: _Camera = None, **settings: Any) -> None:
    """Writes the view as `kappa render -o PATH` does (.png .jpg .svg .pdf, by the extension)."""

class Setting(TypedDict, total=False):
    name: str  # keyword spelling: 'line_width'
    label: str
    help: str
    expects: str
    kind: str  # 'number', 'integer', 'switch', 'choice', 'lines', 'color', 'vector', 'text'
    default: Any
    min: float
    max: float
    logarithmic: bool
    can_be_off: bool
    choices: list[str]

def settings() -> list[Setting]:
    """The appearance settings table (app/appearance_settings.h): names, help, ranges, defaults."""

class LineToggle(TypedDict):
    kind: str
    label: str
    setting: str  # keyword of its threshold or count, '' if none

class LineGroup(TypedDict):
    title: str
    lines: list[LineToggle]

def line_groups() -> list[LineGroup]:
    """The line kinds in the groups of kappa's panel."""

def ink_agreement(a: npt.ArrayLike | _Path, b: npt.ArrayLike | _Path, radius: float = 2.0) -> tuple[float, float]:
    """(fraction of a's ink within radius px of b's, fraction of b's within radius of a's); a and b are
    (h, w, 3|4) uint8 images (ink: darkest channel below 128), (h, w) ink masks or PNG paths."""

class GlContext(TypedDict):
    description: str
    contexts_created: int
    drawings: int

def gl_context() -> GlContext:
    """The module's one GL context (made on the first drawing, reused by every later call)."""

class BatchFailure(TypedDict):
    line: int
    output: str
    reason: str

class BatchReport(TypedDict):
    jobs: int
    written: int
    skipped: int
    failed: list[BatchFailure]
    seconds: float
    summary: str

def batch(
    manifest: Union[_Path, Sequence[str]],
    *,
    shard: tuple[int, int] | None = None,
    skip_existing: bool = True,
    progress: bool = False,
    base_dir: _Path | None = None,
) -> BatchReport:
    """Runs a manifest as `kappa batch` does; never stops at a failure."""

class Job(TypedDict):
    line: int
    mesh: str  # '' for the built-in model
    output: str
    options: list[str]

def read_manifest(manifest: Union[_Path, Sequence[str]], *, base_dir: _Path | None = None) -> list[Job]:
    """The jobs of a manifest with relative paths resolved."""

"""What one kappa call draws: the selected mesh objects of a scene, evaluated with their modifiers,
as one set of world-space triangles, and the view (the scene camera, or the 3D view) in kappa's
terms. Problems are raised as DrawError with the one line the report shows."""
import numpy as np

from . import geometry, view


class DrawError(Exception):
    """A problem with the scene, said in one line for Blender's report."""


def selected_mesh_objects(context):
    objects = [o for o in context.selected_objects if o.type == "MESH"]
    if not objects:
        raise DrawError("kappa lines: no mesh selected: select the mesh objects to draw")
    return objects


def object_triangles(obj, depsgraph):
    """(V float64 (n, 3) world space, F int64 (m, 3)) of the object with its modifiers."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        V = np.empty(len(mesh.vertices) * 3, np.float64)
        mesh.vertices.foreach_get("co", V)
        F = np.empty(len(mesh.loop_triangles) * 3, np.int64)
        mesh.loop_triangles.foreach_get("vertices", F)
    finally:
        evaluated.to_mesh_clear()
    if F.size == 0:
        raise DrawError(f"kappa lines: object '{obj.name}' has no faces: kappa draws surfaces")
    M = np.array(evaluated.matrix_world, np.float64)
    V = V.reshape(-1, 3) @ M[:3, :3].T + M[:3, 3]
    return V, F.reshape(-1, 3)


class SceneMesh:
    """The selected objects' triangles together: V float32 (n, 3) and F uint32 (m, 3), world space."""

    def __init__(self, context):
        depsgraph = context.evaluated_depsgraph_get()
        self.parts = [(o.name, *object_triangles(o, depsgraph)) for o in selected_mesh_objects(context)]
        offsets = np.cumsum([0] + [len(V) for _, V, _ in self.parts])
        self.V = np.concatenate([V for _, V, _ in self.parts]).astype(np.float32)
        self.F = np.concatenate([F + o for (_, _, F), o in zip(self.parts, offsets)]).astype(np.uint32)

    @property
    def face_count(self):
        return len(self.F)

    def check_outside(self, eye):
        for name, V, F in self.parts:
            if geometry.point_inside(V, F, eye):
                raise DrawError(f"kappa lines: the camera is inside '{name}': move it out to draw the lines")


def render_size(scene):
    r = scene.render
    return (max(1, round(r.resolution_x * r.resolution_percentage / 100)),
            max(1, round(r.resolution_y * r.resolution_percentage / 100)))


class View:
    """kappa's camera dict (eye, target, up, fov) and the image size of a view; eye as a numpy point."""

    def __init__(self, camera, size):
        self.camera, self.size = camera, size
        self.eye = np.array(camera["eye"], np.float64)


def scene_camera_view(scene):
    cam = scene.camera
    if cam is None or cam.type != "CAMERA":
        raise DrawError("kappa lines: the scene has no camera: add one or draw from a 3D view")
    data = cam.data
    if data.type != "PERSP":
        raise DrawError(f"kappa lines: camera '{cam.name}' is {data.type.lower()}: kappa draws perspective views only")
    width, height = render_size(scene)
    fov = view.vertical_fov(data.lens, data.sensor_width, data.sensor_height, data.sensor_fit,
                            width * scene.render.pixel_aspect_x, height * scene.render.pixel_aspect_y)
    return View(view.look_at(cam.matrix_world, fov), (width, height))


def viewport_view(region, region_3d):
    if not region_3d.is_perspective:
        raise DrawError("kappa lines: the 3D view is orthographic: kappa draws perspective views only")
    camera = view.look_at(region_3d.view_matrix.inverted(), view.viewport_fov(region_3d.window_matrix))
    return View(camera, (region.width, region.height))


def current_view(context):
    """The scene camera's view; without a scene camera, the 3D view the operator runs in (from its
    sidebar too: the view is the area's main region)."""
    scene = context.scene
    area = getattr(context, "area", None)
    if scene.camera is None and area is not None and area.type == "VIEW_3D":
        region = next(r for r in area.regions if r.type == "WINDOW")
        return viewport_view(region, area.spaces.active.region_3d)
    return scene_camera_view(scene)

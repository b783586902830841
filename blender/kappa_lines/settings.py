"""scene.kappa_lines: kappa's appearance settings as Blender properties, built from kappa's own table
(kappa.settings(), kappa.line_groups(): app/appearance_settings.h), so names, help, slider ranges and
defaults are typed once; and the keywords kappa.strokes takes back from them."""
import bpy

# The settings the panel shows, in its order (kappa.settings() has them all).
SHOWN = ("detail", "line_width", "fade", "width_by_strength", "simplify", "min_stroke", "line_color",
         "hatching", "hatch_spacing", "hidden_lines")


def line_property(kind):
    return "line_" + kind.replace("-", "_")


def _number_property(s, integer=False):
    make = bpy.props.IntProperty if integer else bpy.props.FloatProperty
    cast = int if integer else float
    # The slider's range (kappa's `expects` allows more above it).
    return make(name=s["label"], description=s["help"], default=cast(s["default"]), min=cast(s["min"]),
                soft_max=cast(s["max"]))


def _property(s):
    kind = s["kind"]
    if kind in ("number", "integer"):
        return _number_property(s, kind == "integer")
    if kind == "switch":
        return bpy.props.BoolProperty(name=s["label"], description=s["help"], default=bool(s["default"]))
    if kind == "choice":
        return bpy.props.EnumProperty(name=s["label"], description=s["help"], default=s["default"],
                                      items=[(c, c, "") for c in s["choices"]])
    if kind == "color":
        return bpy.props.FloatVectorProperty(name=s["label"], description=s["help"], subtype="COLOR", size=3,
                                             min=0, max=1, default=tuple(s["default"][:3]))
    raise ValueError(f"kappa setting {s['name']}: no Blender property for kind {kind}")


def settings_by_name(kappa):
    return {s["name"]: s for s in kappa.settings()}


def make_settings_class(kappa):
    """The PropertyGroup class of scene.kappa_lines."""
    table = settings_by_name(kappa)
    annotations = {}
    for name in SHOWN:
        s = table[name]
        annotations[name] = _property(s)
        if s.get("can_be_off"):
            annotations[name + "_on"] = bpy.props.BoolProperty(name="", description=f"{s['label']} on (off: {s['help']})",
                                                               default=float(s["default"]) > 0)
    default_lines = set(table["lines"]["default"])
    for group in kappa.line_groups():
        for line in group["lines"]:
            annotations[line_property(line["kind"])] = bpy.props.BoolProperty(
                name=line["label"], description=f"draw {line['label']} ({table['lines']['help']})",
                default=line["kind"] in default_lines)
            if line["setting"] and line["setting"] not in annotations:
                annotations[line["setting"]] = _property(table[line["setting"]])
    # The add-on's own settings.
    annotations["pull"] = bpy.props.FloatProperty(
        name="Pull to camera", default=0.01, min=0, max=0.5, soft_max=0.1, subtype="FACTOR",
        description="strokes lie on the surface moved this fraction of the way to the camera, so that the "
                    "surface does not hide them in the viewport (the picture does not change)")
    annotations["time_limit"] = bpy.props.FloatProperty(
        name="Time limit", default=20, min=0.5, soft_max=120, unit="TIME_ABSOLUTE",
        description="refuse meshes that would take kappa longer than this per frame (seconds)")
    return type("KappaLinesSettings", (bpy.types.PropertyGroup,), {"__annotations__": annotations})


def all_lines(kappa):
    return [line["kind"] for group in kappa.line_groups() for line in group["lines"]]


def chosen_lines(props, kappa):
    return [kind for kind in all_lines(kappa) if getattr(props, line_property(kind))]


def layer_names(props, kappa, chosen=True):
    """The Grease Pencil layers these settings draw into: the chosen line types (named as kappa's SVG
    layers: contours, suggestive, ...), hatching when it is on, and `hidden` for the dashed hidden
    parts of the lines when hidden lines are on. chosen=False: every layer kappa can draw."""
    kinds = chosen_lines(props, kappa) if chosen else all_lines(kappa)
    names = [("contours" if kind == "silhouette" else kind) for kind in kinds]
    if props.hatching != "none" or not chosen:
        names.append("hatching")
    if props.hidden_lines or not chosen:
        names.append("hidden")
    return list(dict.fromkeys(names))


def keywords(props, kappa):
    """The keywords of kappa.strokes for these settings (all but size and camera)."""
    table = settings_by_name(kappa)
    out = {"lines": chosen_lines(props, kappa) or "none"}
    names = set(SHOWN) | {line["setting"] for g in kappa.line_groups() for line in g["lines"] if line["setting"]}
    for name in names:
        s, value = table[name], getattr(props, name)
        if s.get("can_be_off") and not getattr(props, name + "_on"):
            value = "off" if "off" in s["expects"] else 0
        elif s["kind"] == "color":
            value = "#" + "".join(f"{round(min(max(c, 0), 1) * 255):02x}" for c in value)
        out[name] = value
    return out

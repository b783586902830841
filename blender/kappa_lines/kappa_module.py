"""Finding kappa's Python module: installed (`cmake --install`, on Blender's Python path), or from
the folder set in the add-on's preferences (a build's python/ folder, say build/python)."""
import importlib
import os
import sys

_loaded = None
_problem = "kappa's Python module was not looked for yet"


def load(folder=""):
    """Imports kappa, from `folder` first when given. Returns the module, or None (problem() says why)."""
    global _loaded, _problem
    if _loaded is not None:
        return _loaded
    folder = os.path.abspath(os.path.expanduser(folder)) if folder else ""
    if folder and folder not in sys.path:
        sys.path.insert(0, folder)
    try:
        _loaded = importlib.import_module("kappa")
    except ImportError as e:
        where = f"in {folder} or installed" if folder else "installed (set its folder in the add-on's preferences)"
        _problem = f"kappa's Python module was not found {where}: {e}"
        return None
    return _loaded


def problem():
    return _problem


def module():
    """The loaded module or None."""
    return _loaded

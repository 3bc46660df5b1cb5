"""A tidepool scene file resolved against scenes/default.json, for the Cycles scripts.

tidepool fills every key a scene file leaves out from the built-in default scene,
which scenes/default.json spells out in full (a test keeps the two equal); objects
merge key by key, lists (spheres, boxes, drops) replace the default's whole, and
each sphere's or box's missing keys take their defaults at the script's point of use.
"""
import json
import os

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def merge(base, over):
    out = dict(base)
    for key, value in over.items():
        if isinstance(value, dict) and isinstance(out.get(key), dict):
            out[key] = merge(out[key], value)
        else:
            out[key] = value
    return out


def resolve(path):
    with open(os.path.join(REPO, "scenes", "default.json")) as f:
        default = json.load(f)
    with open(path) as f:
        scene = json.load(f)
    return merge(default, scene)

# SPDX-License-Identifier: Zlib
"""Imports a runner's scene.glb into Blender and checks it against the run's motion.csv.

    blender -b --factory-startup --python scripts/blender_check.py -- SCENE.glb MOTION.csv

Checks: one mesh object per body named in motion.csv; every fragment (a row with a parent) and
every body that moves carries translation/rotation keyframes; every body that broke is hidden
(scale 0) from its removal on. Exits 1 with the reasons when a check fails (make blender-check).
"""
import csv
import sys

import bpy


def main(glb, motion):
    with open(motion, newline="") as f:
        rows = list(csv.DictReader(f))
    parents, moving, removed = {}, set(), set()
    first = {}
    for r in rows:
        parents.setdefault(r["name"], r["parent"])
        key = (r["px"], r["py"], r["pz"], r["qx"], r["qy"], r["qz"], r["qw"])
        if r["name"] in first and first[r["name"]] != key:
            moving.add(r["name"])
        first.setdefault(r["name"], key)
        if r["alive"] == "0":
            removed.add(r["name"])

    bpy.ops.wm.read_factory_settings(use_empty=True)
    # Shading FLAT (the meshes have no normals, so flat is what they mean): the importer's default,
    # NORMALS, fails in Debian 12's Blender 3.4 on Debian's NumPy 1.24 (np.bool is gone).
    bpy.ops.import_scene.gltf(filepath=glb, import_shading="FLAT")
    objects = {o.name: o for o in bpy.data.objects if o.type == "MESH"}
    problems = []
    if set(objects) != set(parents):
        problems.append(f"{len(objects)} mesh objects for {len(parents)} bodies; missing "
                        f"{sorted(set(parents) - set(objects))[:5]}, extra {sorted(set(objects) - set(parents))[:5]}")
    keyed = 0
    for name, parent in parents.items():
        o = objects.get(name)
        if o is None:
            continue
        action = o.animation_data.action if o.animation_data else None
        paths = {c.data_path for c in action.fcurves} if action else set()
        keys = sum(len(c.keyframe_points) for c in action.fcurves) if action else 0
        if (parent or name in moving) and not ({"location", "rotation_quaternion"} <= paths and keys > 0):
            problems.append(f"{name}: no location/rotation keyframes ({sorted(paths)})")
        if name in removed and "scale" not in paths:
            problems.append(f"{name}: broke but has no scale keys to hide it")
        keyed += 1 if keys > 0 else 0
    fragments = sum(1 for p in parents.values() if p)
    print(f"blender_check: {len(objects)} mesh objects, {fragments} fragments, {keyed} with keyframes, "
          f"{len(removed)} hidden after breaking")
    if problems:
        print("blender_check: FAILED\n  " + "\n  ".join(problems[:20]))
        sys.exit(1)
    print("blender_check: passed")


if __name__ == "__main__":
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) != 2:
        print(__doc__)
        sys.exit(2)
    main(*args)

#!/usr/bin/env python3
"""Render a ray1 scene file with Mitsuba 3 (scalar_rgb) and time it, so that ray1's render time can be
compared with a mature renderer's on the same scene. Prints one line of JSON; see README.md.

    python3 render_mitsuba.py SCENE.xml [--spp N] [--repeat K] [--threads T] [--out image.exr|png]
"""
import argparse
import json
import math
import os
import statistics
import sys
import time
import xml.etree.ElementTree as ET

import drjit as dr
import mitsuba as mi
import numpy as np

mi.set_variant("scalar_rgb")


class Unsupported(Exception):
    """A scene this script cannot translate faithfully: reported in one line rather than approximated."""


# The child elements each object may have, in lower case (ray1 matches names case-insensitively).
SHADERS = {"Lambertian": "diffusecolor texture", "Phong": "diffusecolor texture specularcolor exponent",
           "Glazed": "refractiveindex substrate", "RGBNormals": ""}
SURFACES = {"Sphere": "center radius", "Box": "minpt maxpt", "Triangle": "v0 v1 v2 vt0 vt1 vt2", "Mesh": "data",
            "Cylinder": "center radius height", "Group": "surface"}
ALLOWED = {"scene": set("camera image exposure backcolor samples light shader surface texture".split()),
           "camera": set("viewpoint viewdir viewup projdistance viewwidth viewheight".split()),
           "light": {"position", "intensity"},
           **{k: set(v.split()) for k, v in SHADERS.items()},
           **{k: set(v.split()) | {"shader", "translate", "rotate", "scale"} for k, v in SURFACES.items()}}


def tag(el):
    return el.tag.lower()


def checked(el, kind):
    allowed = ALLOWED[kind]
    for c in el:
        if tag(c) not in allowed:
            raise Unsupported(f"unknown element <{c.tag}> in a {kind}; expected one of {', '.join(sorted(allowed))}")
    return el


def first(el, name):
    return next((c for c in el if tag(c) == name), None)


def value(el, name, default, count=3):
    """A property's numbers (one float when count is 1), or the default when it is absent."""
    for c in el:
        if tag(c) == name.lower():
            nums = [float(x) for x in (c.text or "").split()]
            if len(nums) != count:
                raise Unsupported(f"<{c.tag}> needs {count} number(s), got {(c.text or '').strip()!r}")
            return nums[0] if count == 1 else np.array(nums)
    return default if count == 1 or default is None else np.array(default, dtype=float)


def placement(el):
    """ray1's T·Rz·Ry·Rx·S as a 4x4 matrix."""
    m = np.eye(4)
    m[:3, 3] = value(el, "translate", [0, 0, 0])
    for axis in (2, 1, 0):
        degrees = value(el, "rotate", [0, 0, 0])[axis]
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        if degrees % 90 == 0:  # exact, as in ray1, so that turned boxes keep axis-aligned faces
            c, s = round(c), round(s)
        i, j = [(1, 2), (2, 0), (0, 1)][axis]
        r = np.eye(4)
        r[i, i], r[i, j], r[j, i], r[j, j] = c, -s, s, c
        m = m @ r
    return m @ np.diag([*value(el, "scale", [1, 1, 1]), 1])


def uniform_scale(m, what):
    """The scale of a similarity transform: Mitsuba's sphere and cylinder take nothing more general."""
    gram = m[:3, :3].T @ m[:3, :3]
    if not np.allclose(gram, gram[0, 0] * np.eye(3), rtol=1e-6, atol=1e-12):
        raise Unsupported(f"a {what} under a non-uniform scale (e.g. an ellipsoid) has no Mitsuba shape here")
    return math.sqrt(gram[0, 0])


def read_obj(path):
    """ray1's OBJ rules (Mitsuba's own loader rejects negative indices): polygons become fans around their
    first corner. Returns positions, normals and triangles of (v, vn or None) index pairs."""
    v, vn, tris = [], [], []
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            w = line.split("#", 1)[0].split()
            if w and w[0] in ("v", "vn"):
                (v if w[0] == "v" else vn).append([float(x) for x in w[1:4]])
            elif w and w[0] == "f":
                corners = []
                for c in w[1:]:
                    vi, _, ni = (c.split("/") + ["", ""])[:3]
                    corners.append((int(vi) - 1 if int(vi) > 0 else len(v) + int(vi),
                                    None if not ni else int(ni) - 1 if int(ni) > 0 else len(vn) + int(ni)))
                tris += [(corners[0], corners[k], corners[k + 1]) for k in range(1, len(corners) - 1)]
    return np.array(v), np.array(vn), tris


class Translator:
    """Builds the Mitsuba scene dictionary; every shape gets a `diffuse` BSDF of its shader's kd."""

    def __init__(self, scene_path):
        self.folder = os.path.dirname(os.path.abspath(scene_path))
        self.named, self.shapes, self.dropped = {}, {}, set()  # dropped: shading Mitsuba will not show

    def shader_color(self, el, kind="shader"):
        if el.get("ref") is not None:
            if el.get("ref") not in self.named:
                raise Unsupported(f"<{kind} ref=\"{el.get('ref')}\"> names no shader defined before it")
            return self.named[el.get("ref")]
        st = el.get("type", "")
        if st not in SHADERS:
            raise Unsupported(f"unknown shader type \"{st}\" in <{el.tag}>")
        if any(tag(c) == "texture" for c in checked(el, st)):
            raise Unsupported(f"textures are not translated (in a {st} shader)")
        if st == "Glazed":  # the substrate alone: the mirror term is dropped
            self.dropped.add("Glazed reflection")
            sub = first(el, "substrate")
            return np.ones(3) if sub is None else self.shader_color(sub, "substrate")
        if st != "Lambertian":
            self.dropped.add({"Phong": "Phong highlights", "RGBNormals": "RGBNormals (shown white)"}[st])
        return value(el, "diffuseColor", [1, 1, 1])

    @staticmethod
    def bsdf(color):
        return {"type": "diffuse", "reflectance": {"type": "rgb", "value": [float(c) for c in color]}}

    def add(self, shape):
        self.shapes[f"shape{len(self.shapes)}"] = shape

    def mesh(self, positions, faces, normals, world, color):
        """A mesh placed by world (normals by its inverse transpose). Under a mirror the winding flips, so
        that the face normal stays ray1's: (v1 - v0) x (v2 - v0) carried by the inverse transpose."""
        p = (np.c_[positions, np.ones(len(positions))] @ world.T)[:, :3]
        faces = np.asarray(faces, dtype=np.uint32)[:, [0, 2, 1] if np.linalg.det(world[:3, :3]) < 0 else [0, 1, 2]]
        props = mi.Properties()
        props["bsdf"] = mi.load_dict(self.bsdf(color))
        m = mi.Mesh(f"mesh{len(self.shapes)}", len(p), len(faces), props, has_vertex_normals=normals is not None)
        params = mi.traverse(m)
        params["vertex_positions"] = p.astype(np.float32).ravel()
        params["faces"] = faces.ravel()
        if normals is not None:
            n = normals @ np.linalg.inv(world[:3, :3])  # rows: (M^-T n)^T = n^T M^-1
            params["vertex_normals"] = (n / np.linalg.norm(n, axis=1, keepdims=True)).astype(np.float32).ravel()
        params.update()
        self.add(m)

    def obj_mesh(self, path, world, color):
        v, vn, tris = read_obj(path)
        for smooth in (False, True):  # as in ray1: faces with vn are smooth-shaded, faces without flat
            index, faces = {}, []  # vertices (or vertex-normal pairs) shared between faces, as in the file
            for tri in tris:
                if all(n is not None for _, n in tri) == smooth:
                    faces.append([index.setdefault(c if smooth else c[0], len(index)) for c in tri])
            if faces:
                keys = list(index)
                self.mesh(v[[k[0] if smooth else k for k in keys]], faces,
                          vn[[k[1] for k in keys]] if smooth else None, world, color)

    def surface(self, el, parent, inherited):
        kind = el.get("type", "")
        if kind not in SURFACES:
            raise Unsupported(f"unknown surface type \"{kind}\"")
        own = first(checked(el, kind), "shader")
        color = inherited if own is None else self.shader_color(own)
        world = parent @ placement(el)
        if kind == "Group":  # its shader goes to every child without one of its own
            for c in el:
                if tag(c) == "surface":
                    self.surface(c, world, color)
            return
        color = np.ones(3) if color is None else color
        if kind == "Sphere":
            center = (world @ [*value(el, "center", [0, 0, 0]), 1])[:3]
            radius = uniform_scale(world, "Sphere") * value(el, "radius", 1.0, 1)
            self.add({"type": "sphere", "center": center.tolist(), "radius": radius, "bsdf": self.bsdf(color)})
        elif kind == "Box":  # 12 triangles, as ray1's, so that any placement works
            lo, hi = value(el, "minPt", [0, 0, 0]), value(el, "maxPt", [1, 1, 1])
            corners = np.array([[(hi if i >> a & 1 else lo)[a] for a in range(3)] for i in range(8)])
            quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]  # outward
            self.mesh(corners, [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], None, world, color)
        elif kind == "Triangle":
            verts = [value(el, k, None) for k in ("v0", "v1", "v2")]
            if any(x is None for x in verts):
                raise Unsupported("a Triangle needs <v0>, <v1> and <v2>")
            self.mesh(np.array(verts), [(0, 1, 2)], None, world, color)
        elif kind == "Mesh":
            data = first(el, "data")
            if data is None or not data.text:
                raise Unsupported("a Mesh needs <data>")
            self.obj_mesh(os.path.join(self.folder, data.text.strip()), world, color)
        else:  # Cylinder. Mitsuba's is open; ray1's is capped, hence two disks
            s, base = uniform_scale(world, "Cylinder"), value(el, "center", [0, 0, 0])
            r = s * value(el, "radius", 1.0, 1)
            p0, p1 = ((world @ [*(base + [0, y, 0]), 1])[:3] for y in (0, value(el, "height", 1.0, 1)))
            self.add({"type": "cylinder", "p0": p0.tolist(), "p1": p1.tolist(), "radius": r, "bsdf": self.bsdf(color)})
            axis = (p1 - p0) / np.linalg.norm(p1 - p0)
            for centre, n in ((p0, -axis), (p1, axis)):  # look_at turns the disk's normal, local +z, to n
                frame = mi.ScalarTransform4f().look_at(origin=centre.tolist(), target=(centre + n).tolist(),
                                                       up=[1, 0, 0] if abs(n[0]) < 0.9 else [0, 1, 0])
                self.add({"type": "disk", "to_world": frame @ mi.ScalarTransform4f().scale([r, r, 1]),
                          "bsdf": self.bsdf(color)})

    def translate(self, root, spp, emitter_samples=None):
        if tag(root) != "scene":
            raise Unsupported(f"the root element is <{root.tag}>, not <scene>")
        cam = first(checked(root, "scene"), "camera")
        if cam is None or cam.get("type") != "PerspectiveCamera":
            raise Unsupported("only a <camera type=\"PerspectiveCamera\"> is translated")
        image = (first(root, "image").text or "").split() if first(root, "image") is not None else []
        if len(image) != 2:
            raise Unsupported("the scene needs <image>width height</image>")
        width, height = int(image[0]), int(image[1])
        view_w, view_h = value(checked(cam, "camera"), "viewWidth", 1.0, 1), value(cam, "viewHeight", 1.0, 1)
        if abs(view_w / view_h * height / width - 1) > 1e-6:
            print("warning: viewWidth/viewHeight differs from the image's aspect ratio; Mitsuba's pixels are "
                  "square, so the vertical field of view will not be ray1's", file=sys.stderr)
        for el in root:
            if tag(el) == "shader":
                if el.get("name") is None:
                    raise Unsupported("a top-level <shader> needs a name")
                self.named[el.get("name")] = self.shader_color(el)
            elif tag(el) == "surface":
                self.surface(el, np.eye(4), None)
            elif tag(el) == "texture":
                raise Unsupported("textures are not translated")
        lights = [checked(el, "light") for el in root if tag(el) == "light"]
        k = emitter_samples or max(1, len(lights))
        for el in lights:
            # ray1: kd·I·cos/r². Mitsuba: (kd/π)·I·cos/r², I in W/sr: hence the π. The 1/k: Mitsuba's `direct`
            # sums, not averages, its k emitter samples when they land on delta lights (MIS weight 1, not 1/k).
            intensity = value(el, "intensity", [1, 1, 1]) * math.pi / k
            self.add({"type": "point", "position": value(el, "position", [0, 0, 0]).tolist(),
                      "intensity": {"type": "rgb", "value": intensity.tolist()}})
        eye = value(cam, "viewPoint", [0, 0, 0])
        self.shapes.update({
            "type": "scene",
            # k shadow rays per hit, each to a light picked at random (ray1 visits every light once).
            "integrator": {"type": "direct", "emitter_samples": k, "bsdf_samples": 0},
            "sensor": {
                "type": "perspective", "fov_axis": "x", "near_clip": 1e-4, "far_clip": 1e7,
                "fov": math.degrees(2 * math.atan(view_w / 2 / value(cam, "projDistance", 1.0, 1))),
                "to_world": mi.ScalarTransform4f().look_at(
                    origin=eye.tolist(), target=(eye + value(cam, "viewDir", [0, 0, -1])).tolist(),
                    up=value(cam, "viewUp", [0, 1, 0]).tolist()),
                "sampler": {"type": "independent", "sample_count": spp},
                "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                         "pixel_format": "rgb"},
            },
        })
        return self.shapes, width, height, len(lights), k


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene")
    ap.add_argument("--spp", type=int, help="samples per pixel, overriding the scene's <samples>")
    ap.add_argument("--repeat", type=int, default=5, help="timed renders after one warm-up (default 5)")
    ap.add_argument("--threads", type=int, default=os.cpu_count(), help="render threads (default: all cores)")
    ap.add_argument("--emitter-samples", type=int, help="shadow rays per hit (default: the number of lights)")
    ap.add_argument("--out", help="also write the last image: .png (ray1's tone map) or .exr (linear)")
    a = ap.parse_args()
    if a.repeat < 1 or a.threads < 1 or any(x is not None and x < 1 for x in (a.spp, a.emitter_samples)):
        ap.error("--spp, --repeat, --threads and --emitter-samples must be at least 1")
    # The size of nanothread's pool, on which Mitsuba's scalar renderer runs its image blocks.
    dr.set_thread_count(a.threads)
    try:
        root = ET.parse(a.scene).getroot()
        requested = a.spp if a.spp is not None else int(value(root, "samples", 1.0, 1))
        spp = max(1, round(math.sqrt(requested))) ** 2  # ray1 traces an n×n grid, n = round(√N)
        exposure = value(root, "exposure", 1.0, 1)
        tr = Translator(a.scene)
        desc, width, height, nlights, k = tr.translate(root, spp, a.emitter_samples)
        scene = mi.load_dict(desc)
    except (Unsupported, ET.ParseError, OSError, ValueError, RuntimeError) as e:
        print(f"{a.scene}: {e}", file=sys.stderr)
        sys.exit(2)
    if tr.dropped:
        print(f"note: rendered as plain diffuse, without: {', '.join(sorted(tr.dropped))}", file=sys.stderr)

    def render():
        # Scalar mode renders eagerly: the image is complete when mi.render returns. The copy to NumPy
        # (about 20 µs) would force the evaluation in an llvm variant, so the timing stays honest there too.
        return np.array(mi.render(scene, spp=spp))

    render()  # warm-up: first-touch allocations and lazy initialisation stay out of the figures
    times = []
    for _ in range(a.repeat):
        start = time.perf_counter()
        image = render()
        times.append(time.perf_counter() - start)
    if a.out and a.out.lower().endswith(".png"):
        # ray1's tone map: exposure × L, clamped to [0, 1], gamma 1/2.2, floor(255x + ½).
        x = np.clip(np.nan_to_num(image * exposure), 0, 1) ** (1 / 2.2)
        mi.Bitmap(np.floor(255 * x + 0.5).astype(np.uint8), mi.Bitmap.PixelFormat.RGB).write(a.out)
    elif a.out:
        mi.Bitmap(image, mi.Bitmap.PixelFormat.RGB).write(a.out)
    print(json.dumps({
        "scene": a.scene, "variant": mi.variant(), "spp": spp, "width": width, "height": height,
        "threads": dr.thread_count(), "lights": nlights, "emitter_samples": k, "repeat": a.repeat,
        "render_seconds_best": min(times), "render_seconds_median": statistics.median(times),
        "mitsuba_version": mi.__version__,
    }))


if __name__ == "__main__":
    main()

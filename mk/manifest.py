#!/usr/bin/env python3
"""manifest.py — a scene's manifest (firmware/scenes/<scene>.manifest.toml) as a make fragment.

usage: manifest.py SCENE [--out FILE]     write the fragment (stdout without --out)
       manifest.py --check [SCENE ...]    validate (every scene of the table without names)
       manifest.py --file PATH [--out F]  a manifest at another path (the tests' bad manifests)

A manifest names what its scene needs; everything else is left out of the build. Its keys, all
required (a missing, unknown or out-of-range one is refused with the file and the key):
  scene                  the scene's name, as in firmware/scenes/scene_list.h
  [features] lines       GPU line primitives (ENABLE_LINES); without them the wireframe is
                         emulated with triangles (FW_WITH_LINE_EMULATION) and the frame reserves
                         the table's wverts/wprims columns
             depth       the depth buffer (ENABLE_ZBUF) and the firmware's depth test (FW_WITH_DEPTH)
             lighting    flat light per face (FW_WITH_LIGHTING)
             anaglyph    the G key's red/cyan stereo (FW_WITH_ANAGLYPH)
             wireframe   the F key's outline mode (FW_WITH_WIREFRAME)
  [gpu]      span_w      pixels per clock, 1 4 8 16 (SPAN_W)
             vtx_cap     vertex buffer, a power of two 4..1024 (VTX_CAP): at least the scene's
                         frame vertices (verts, or wverts with emulated lines) or the contract's
                         1024 where a frame needs more (the driver then splits it into batches)
             tri_cap     index buffer, a power of two 4..512 (TRI_CAP), likewise for prims/wprims
The model scene's line of the table takes its columns from its capacities (scenes/model/model.h),
so its manifest has one table more, required there and refused elsewhere:
  [model]    upload      models uploaded over the UART (FW_WITH_UPLOAD: the receiver and its
                         staging buffer, one mesh file of the capacity below)
             max_verts   the mesh's vertices (FW_MODEL_MAX_VERTS), 4..65536: the faces' 16-bit
                         indices (render/mesh.h)
             max_faces   the mesh's faces (FW_MODEL_MAX_FACES), 4..65536, likewise (normal index)
             sdram_max_verts, sdram_max_faces   the same where the firmware runs from the SDRAM
                         (SOC_MEM=sdram, docs/boot.md): its capacities then
           the scene's columns are model.h's MODEL_FRAME_* / MODEL_WIRE_* macros evaluated at
           these capacities (read from model.h, not written twice)

A manifest names no RAM size: the SoC's RAM is what the scene's linked image needs, read off the
link (bsp/soc/postlink.py's <elf>.ramkib; mk/manifest.mk builds the firmware first, then the
RAM of that size).

The fragment sets, with `override` (a manifest build is what the file says, whatever else the
command line asks): FW_SCENE_SET=one, FW_LINE_EMULATION, FW_DEFS (the FW_WITH_* switches),
SPAN_W, ZBUF, FW_MODEL_MAX_VERTS / FW_MODEL_MAX_FACES (the model scene's, and FW_WITH_UPLOAD
in FW_DEFS; for another scene the model's on-chip ones, which keep its frame's indices narrow), and MANIFEST_GPU_GFLAGS / MANIFEST_GPU_TAG (the GPU's parameters
beyond SPAN_W and ENABLE_ZBUF, as Verilator -G flags and as a directory name; both empty when
they are the defaults, so such a scene shares the default simulators).
"""
import argparse
import os
import re
import sys
import tomllib

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SCENE_TABLE = os.path.join(ROOT, "firmware/scenes/scene_list.h")
CONTRACT = os.path.join(ROOT, "contract/gpu_contract.toml")
BUILD_OPTIONS_H = os.path.join(ROOT, "firmware/config/build_options.h")

SCHEMA = {
    "scene": str,
    "features": {"lines": bool, "depth": bool, "lighting": bool, "anaglyph": bool, "wireframe": bool},
    "gpu": {"span_w": int, "vtx_cap": int, "tri_cap": int},
}
# The [model] table, for the scenes whose table line takes its columns from model.h's macros.
MODEL_SCHEMA = {"upload": bool, "max_verts": int, "max_faces": int, "sdram_max_verts": int, "sdram_max_faces": int}
MODEL_CAP_MAX = 65536  # 16-bit vertex and normal indices in struct mesh_face (render/mesh.h)


class ManifestError(Exception):
    pass


def manifest_path(scene):
    return os.path.join(ROOT, "firmware/scenes", f"{scene}.manifest.toml")


def scene_table():
    """{name: {verts, prims, wverts, wprims}} of the table's numeric lines, {name: None} for a line
    whose columns are macros (the model scene's: model_columns computes them)."""
    rows = {}
    line = re.compile(r"^SCENE\((\w+),\s*(\d+),\s*(\d+),\s*(\d+),\s*(\d+),\s*(\d+),\s*(\d+)\)")
    macro_line = re.compile(r"^SCENE\((\w+),\s*MODEL_STATE_COLUMN,")
    with open(SCENE_TABLE) as f:
        for text in f:
            m = line.match(text)
            if m:
                v = [int(x) for x in m.groups()[1:]]
                rows[m.group(1)] = dict(state=v[0], objects=v[1], verts=v[2], prims=v[3], wverts=v[4], wprims=v[5])
            elif macro_line.match(text):
                rows[macro_line.match(text).group(1)] = None
    return rows


def model_columns(max_verts, max_faces):
    """The model line's verts/prims/wverts/wprims at these capacities: config/build_options.h's
    FW_MODEL_FRAME_* and FW_MODEL_WIRE_* definitions (which model.h's MODEL_FRAME_* and MODEL_WIRE_*
    name) evaluated (C's unsigned integer arithmetic on small values: the same numbers with //
    for /)."""
    with open(BUILD_OPTIONS_H) as f:
        text = f.read()
    cols = {}
    for col, macro in (("verts", "FW_MODEL_FRAME_VERTS"), ("prims", "FW_MODEL_FRAME_PRIMS"),
                       ("wverts", "FW_MODEL_WIRE_VERTS"), ("wprims", "FW_MODEL_WIRE_PRIMS")):
        m = re.search(r"^#define %s\(([a-z, ]+)\) (.+)$" % macro, text, re.M)
        if not m:
            raise ManifestError(f"{os.path.relpath(BUILD_OPTIONS_H, ROOT)}: no #define {macro}(...)")
        expr = re.sub(r"\b(\d+)u\b", r"\1", m.group(2)).replace("/", "//")
        values = {"v": max_verts, "f": max_faces}
        for param in (p.strip() for p in m.group(1).split(",")):
            expr = re.sub(r"\b%s\b" % param, str(values[param]), expr)
        if not re.fullmatch(r"[\d\s+*/()-]+", expr):
            raise ManifestError(f"{os.path.relpath(BUILD_OPTIONS_H, ROOT)}: {macro} is not arithmetic on the capacities: {m.group(2)}")
        cols[col] = eval(expr)  # digits and operators only, checked above
    return cols


def limits():
    with open(CONTRACT, "rb") as f:
        lim = tomllib.load(f)["limits"]
    return lim["vtx_cap"], lim["tri_cap"]


def check_shape(data, schema, where, path):
    for key in data:
        if key not in schema:
            raise ManifestError(f"{path}: unknown key '{where}{key}' (known: {', '.join(schema)})")
    for key, kind in schema.items():
        if key not in data:
            raise ManifestError(f"{path}: missing key '{where}{key}'")
        value = data[key]
        if isinstance(kind, dict):
            if not isinstance(value, dict):
                raise ManifestError(f"{path}: '{where}{key}' must be a table [{key}]")
            check_shape(value, kind, f"{key}.", path)
        elif type(value) is not kind:  # bool is an int in Python: compare types exactly
            raise ManifestError(f"{path}: '{where}{key}' must be {kind.__name__}, not {value!r}")


def power_of_two(n):
    return n > 0 and n & (n - 1) == 0


def load(path, scene=None):
    """The manifest at path, validated; returns its data."""
    try:
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except FileNotFoundError:
        raise ManifestError(f"{path}: no such manifest (every scene has one: firmware/scenes/<scene>.manifest.toml)")
    except tomllib.TOMLDecodeError as e:
        raise ManifestError(f"{path}: not TOML: {e}")
    table = scene_table()
    name = data.get("scene")
    is_model = isinstance(name, str) and name in table and table[name] is None
    if "memory" in data:  # manifests once named their RAM; a size typed by hand went stale
        raise ManifestError(f"{path}: [memory]: a manifest names no RAM size: the build reads it off the "
                            "linked image (bsp/soc/postlink.py, <elf>.ramkib)")
    check_shape(data, dict(SCHEMA, model=MODEL_SCHEMA) if is_model else SCHEMA, "", path)
    if scene is not None and name != scene:
        raise ManifestError(f"{path}: scene = '{name}', but the file is the manifest of '{scene}'")
    if name not in table:
        raise ManifestError(f"{path}: scene '{name}' is not a line of {os.path.relpath(SCENE_TABLE, ROOT)}")
    if is_model:
        for key in ("max_verts", "max_faces", "sdram_max_verts", "sdram_max_faces"):
            if not 4 <= data["model"][key] <= MODEL_CAP_MAX:
                raise ManifestError(f"{path}: model.{key} = {data['model'][key]}: from 4 to {MODEL_CAP_MAX} "
                                    "(16-bit indices, render/mesh.h)")
        # No frame check: a frame past 65,536 vertices or primitives takes wide indices by itself
        # (config/build_options.h FW_RENDER_WIDE_INDEX), and at MODEL_CAP_MAX faces the widest
        # column, the emulated outline's 983,044 vertices, is far inside a wide frame's 2^24
        # (render.h RENDER_INDEX_LIMIT, which RENDER_FRAME_STORAGE asserts at compile time).
        table = dict(table, **{name: model_columns(data["model"]["max_verts"], data["model"]["max_faces"])})
    feat, gpu = data["features"], data["gpu"]
    vtx_max, tri_max = limits()
    if gpu["span_w"] not in (1, 4, 8, 16):
        raise ManifestError(f"{path}: gpu.span_w = {gpu['span_w']}: one of 1, 4, 8, 16")
    for key, top in (("vtx_cap", vtx_max), ("tri_cap", tri_max)):
        if not (4 <= gpu[key] <= top and power_of_two(gpu[key])):
            raise ManifestError(f"{path}: gpu.{key} = {gpu[key]}: a power of two from 4 to {top} (the contract's limit)")
    emulated = feat["wireframe"] and not feat["lines"]
    row = table[name]
    for key, col, top in (("vtx_cap", "verts", vtx_max), ("tri_cap", "prims", tri_max)):
        column = ("w" + col) if emulated else col
        need = min(row[column], top)
        if gpu[key] < need:
            raise ManifestError(f"{path}: gpu.{key} = {gpu[key]} is smaller than scene {name}'s {column} column "
                                f"({row[column]}, scene_list.h): at least {need}")
    return data


def gpu_extra(data):
    """The GPU's parameters where they differ from the defaults: (tag word, Verilator flag) pairs."""
    feat, gpu = data["features"], data["gpu"]
    vtx_max, tri_max = limits()
    extra = []
    if not feat["lines"]:
        extra.append(("l0", "-GENABLE_LINES=0"))
    if not feat["anaglyph"]:  # the write mask's planes serve the anaglyph only: 4 EBR saved
        extra.append(("m0", "-GENABLE_WMASK=0"))
    if gpu["vtx_cap"] != vtx_max:
        extra.append((f"v{gpu['vtx_cap']}", f"-GVTX_CAP={gpu['vtx_cap']}"))
    if gpu["tri_cap"] != tri_max:
        extra.append((f"t{gpu['tri_cap']}", f"-GTRI_CAP={gpu['tri_cap']}"))
    return tuple(extra)


def fragment(data, path):
    feat, gpu = data["features"], data["gpu"]
    b = lambda v: 1 if v else 0
    defs = " ".join(f"-DFW_WITH_{k.upper()}={b(feat[k])}" for k in ("wireframe", "anaglyph", "depth", "lighting"))
    extra = gpu_extra(data)
    tag = "-".join(t for t, _ in extra)
    model = []
    if "model" in data:
        defs += f" -DFW_WITH_UPLOAD={b(data['model']['upload'])}"
        m = data["model"]
        sdram = "$(filter sdram,$(SOC_MEM))"  # the command line's SOC_MEM (bsp/soc/soc_ram.mk)
        model = [f"override FW_MODEL_MAX_VERTS := $(if {sdram},{m['sdram_max_verts']},{m['max_verts']})",
                 f"override FW_MODEL_MAX_FACES := $(if {sdram},{m['sdram_max_faces']},{m['max_faces']})"]
    else:
        # The model scene is not built, so its capacities size nothing but the frame's index
        # width (config/build_options.h): its on-chip ones, so that SOC_MEM=sdram's 65,536 faces
        # do not give this scene wide indices it never needs.
        m = load(manifest_path("model"), "model")["model"]
        model = [f"override FW_MODEL_MAX_VERTS := {m['max_verts']}",
                 f"override FW_MODEL_MAX_FACES := {m['max_faces']}"]
    return "\n".join([
        f"# Generated by mk/manifest.py from {os.path.relpath(path, ROOT)}: do not edit.",
        f"MANIFEST_SCENE       := {data['scene']}",
        "override FW_SCENE_SET := one",
        f"override FW_LINE_EMULATION := {b(feat['wireframe'] and not feat['lines'])}",
        f"override FW_DEFS     := {defs}",
        f"override SPAN_W      := {gpu['span_w']}",
        f"override ZBUF        := {b(feat['depth'])}",
        *model,
        f"MANIFEST_LINES       := {b(feat['lines'])}",
        f"MANIFEST_VTX_CAP     := {gpu['vtx_cap']}",
        f"MANIFEST_TRI_CAP     := {gpu['tri_cap']}",
        f"MANIFEST_GPU_GFLAGS  := {' '.join(g for _, g in extra)}",
        f"MANIFEST_GPU_TAG     := {tag}",
        "",
    ])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenes", nargs="*")
    ap.add_argument("--check", action="store_true", help="validate only")
    ap.add_argument("--file", help="a manifest at another path")
    ap.add_argument("--out")
    args = ap.parse_args()
    try:
        if args.check:
            names = args.scenes or list(scene_table())
            for s in names:
                load(manifest_path(s), s)
            if args.file:
                load(args.file)
            print(f"manifest: {len(names) + (1 if args.file else 0)} manifests valid")
            return 0
        if args.file:
            path, scene = args.file, None
        elif len(args.scenes) == 1:
            path, scene = manifest_path(args.scenes[0]), args.scenes[0]
        else:
            ap.error("one SCENE, or --file, or --check")
        text = fragment(load(path, scene), path)
    except ManifestError as e:
        print(f"manifest: {e}", file=sys.stderr)
        return 1
    if args.out:
        os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
        with open(args.out, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""gen_builds.py — the build table (mk/builds.toml) and the suites (tests/suites.toml) as make and shell.

usage: gen_builds.py --out DIR          write DIR/builds.mk (the lists, read first), DIR/gpusim.mk
                                        (the GPU simulators' rules), DIR/socsim.mk (the SoC
                                        simulators', read by cosim/soc/socsim.mk) and DIR/firmware.mk
                                        (the firmware's object variants and programs, read by
                                        firmware/firmware.mk)
       gen_builds.py --needs 'GLOBS'    the make targets the suites matching GLOBS need (make
                                        expressions, for the Makefile's $(eval))
       gen_builds.py --suites           the suites as tests/run_all.sh's `suite` lines
       gen_builds.py --check            both tables valid, every id a suite names defined
       gen_builds.py --stats            how many builds the table names, how many rules it makes

Everything that can be computed comes from where it is stated: the scenes from scene_list.h, the
GPU's parameters and their defaults from the contract's [build] table, the manifests' GPUs from
the manifests (mk/manifest.py's tags). An error names the file and the key.
"""
import argparse
import fnmatch
import functools
import itertools
import os
import re
import sys
import tomllib

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
BUILDS = os.path.join(ROOT, "mk/builds.toml")
SUITES = os.path.join(ROOT, "tests/suites.toml")
CONTRACT = os.path.join(ROOT, "contract/gpu_contract.toml")
SOC_MAP = os.path.join(ROOT, "contract/soc_map.toml")
SCENE_TABLE = os.path.join(ROOT, "firmware/scenes/scene_list.h")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import manifest  # noqa: E402  (mk/manifest.py: the manifests' GPU tags)
sys.path.insert(0, os.path.join(ROOT, "contract"))
import gen_contract  # noqa: E402  (contract/gen_contract.py: LIMIT_PARAMS, cap_max)

GPU_KEYS = {"params", "display", "trace", "list"}
FW_ROW_KEYS = {"scene", "variant", "elf", "host", "frames", "polls", "defs", "set", "list"}
PLACEHOLDER = re.compile(r"\{([A-Za-z_][A-Za-z0-9_-]*)\}")


class TableError(Exception):
    pass


def load(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


def scenes():
    text = open(SCENE_TABLE).read()
    return re.findall(r"^SCENE\(([A-Za-z0-9_]+)[,)]", text, re.M)


def contract_params():
    """The GPU's build parameters and their defaults: the limits that are parameters (the
    capacities and the frame), then the [build] table, as contract/gen_contract.py declares them
    (its LIMIT_PARAMS, read from it)."""
    c = load(CONTRACT)
    params = {name: c["limits"][key] for name, (key, _) in gen_contract.LIMIT_PARAMS.items()}
    params.update({k: v["default"] for k, v in c["build"].items()})
    return params


@functools.cache
def cap_maxima():
    """The largest buffer capacities (VTX_CAP, TRI_CAP): what their windows hold, as
    contract/gen_contract.py computes them (read once)."""
    return gen_contract.cap_max(load(CONTRACT))


def resolve_max(params, where):
    """A capacity given as "max" becomes its window's (cap_maxima); "max" for any other
    parameter is an error."""
    maxima = cap_maxima()
    out = {}
    for k, v in params.items():
        if v == "max":
            if k not in maxima:
                raise TableError(f"{where}: {k} = \"max\": only {' and '.join(maxima)} have a maximum")
            v = maxima[k]
        out[k] = v
    return out


def expand(pattern, lists):
    """Every combination of the list-valued keys of `lists`, with the pattern filled in."""
    keys = [k for k, v in lists.items() if isinstance(v, list)]
    for combo in itertools.product(*(lists[k] for k in keys)):
        values = dict(lists, **dict(zip(keys, combo)))
        yield pattern.format_map({k: str(v) for k, v in values.items()}), values


# ---- GPU simulators -----------------------------------------------------------------------------
def gpusims(table):
    """id -> (Verilator -G flags, display), in the table's order, manifests' GPUs after."""
    defaults = contract_params()
    out = {}

    def add(ident, params, display, where, trace=False):
        for name in params:
            if name not in defaults:
                raise TableError(f"{where}: {name} is not a build parameter of {CONTRACT}")
        if display not in ("pins", "fast"):
            raise TableError(f"{where}: display = {display!r}: pins or fast")
        if ident in out:
            raise TableError(f"{where}: simulator {ident} named twice")
        # SPAN_W always (the harness's gpu_build.h needs it), the others where they differ.
        params = resolve_max(dict({"SPAN_W": defaults["SPAN_W"]}, **params), where)
        flags = " ".join(f"-G{k}={v}" for k, v in params.items() if v != defaults[k] or k == "SPAN_W")
        out[ident] = (flags + (" --trace-fst" if trace else ""), display, trace)

    for family, spec in table.get("gpusim", {}).items():
        where = f"{BUILDS}: gpusim.{family}"
        unknown = set(spec) - GPU_KEYS
        if unknown:
            raise TableError(f"{where}: unknown key {sorted(unknown)[0]}")
        params = spec.get("params", {})
        for ident, values in expand(family, params):
            add(ident, values, spec.get("display", "pins"), where, spec.get("trace", False))
    spec = table.get("manifest_gpusims")
    if spec:
        if set(spec) != {"SPAN_W", "gouraud", "largest_frame"}:
            raise TableError(f"{BUILDS}: manifest_gpusims: keys SPAN_W, gouraud and largest_frame, "
                             "and no other")
        lim = load(CONTRACT)["limits"]
        # mk/manifest.mk's tags in its order: the manifest's, g1 (GOURAUD=1), f<width> (FB=).
        gouraud = ("g1", ["-GENABLE_GOURAUD=1"])
        largest = (f"f{lim['fb_max_width']}",
                   [f"-GFB_WIDTH={lim['fb_max_width']}", f"-GFB_HEIGHT={lim['fb_max_height']}"])
        tags = set()
        for scene in scenes():
            data = manifest.load(manifest.manifest_path(scene), scene)
            tags.add(manifest.gpu_extra(data))
        for extra in sorted(tags):
            for w in spec["SPAN_W"]:
                for g in spec["gouraud"]:
                    for f in spec["largest_frame"]:
                        full = [(t, [flag]) for t, flag in extra] + ([gouraud] if g else []) + \
                               ([largest] if f else [])
                        if not full:
                            continue  # the default GPU: the table's own simulators
                        tag = "-".join(t for t, _ in full)
                        params = {"SPAN_W": w}
                        for _, flags in full:
                            for flag in flags:
                                k, v = flag[2:].split("=")
                                params[k] = int(v)
                        for display, prefix in (("pins", "sim-cfg"), ("fast", "sim-fast-cfg")):
                            add(f"{prefix}-w{w}-{tag}", params, display,
                                f"{BUILDS}: manifest_gpusims ({tag})")
    return out


# ---- SoC simulators ------------------------------------------------------------------------------
def socsims(table):
    """id -> (system, RAM KiB, GPU -G flags, trace, UART baud or None, USB host, projection unit)."""
    defaults = contract_params()
    ram = [r for r in load(SOC_MAP)["region"] if r["name"] == "RAM"][0]
    out = {}
    for family, spec in table.get("socsim", {}).items():
        where = f"{BUILDS}: socsim.{family}"
        unknown = set(spec) - {"system", "ram", "params", "trace", "uart_baud", "usb", "proj_unit"}
        if unknown:
            raise TableError(f"{where}: unknown key {sorted(unknown)[0]}")
        system = spec.get("system", "soc")
        if system not in ("soc", "ulx3s", "sdram", "ulx3s-sdram"):
            raise TableError(f"{where}: system = {system!r}: soc, ulx3s, sdram or ulx3s-sdram")
        size = spec.get("ram", "default")
        if size not in ("default", "window", "boot"):
            raise TableError(f"{where}: ram = {size!r}: default, window or boot (sizes are the contract's)")
        ram_kib = ram[f"{size}_bytes"] // 1024
        params = resolve_max(dict({"SPAN_W": defaults["SPAN_W"]}, **spec.get("params", {})), where)
        for name in params:
            if name not in defaults:
                raise TableError(f"{where}: {name} is not a build parameter of {CONTRACT}")
        ident = family.format(RAM_KIB=ram_kib)
        if ident in out:
            raise TableError(f"{where}: SoC simulator {ident} named twice")
        flags = " ".join(f"-G{k}={v}" for k, v in params.items() if v != defaults[k] or k == "SPAN_W")
        baud = spec.get("uart_baud")
        if baud is not None and (not isinstance(baud, int) or baud <= 0):
            raise TableError(f"{where}: uart_baud = {baud!r}: bits per second, a positive integer")
        usb = spec.get("usb", False)
        if not isinstance(usb, bool):
            raise TableError(f"{where}: usb = {usb!r}: true or false")
        proj_unit = spec.get("proj_unit", True)
        if not isinstance(proj_unit, bool):
            raise TableError(f"{where}: proj_unit = {proj_unit!r}: true or false")
        out[ident] = (system, ram_kib, flags, bool(spec.get("trace", False)), baud, usb, proj_unit)
    return out


def socsim_mk(socs):
    lines = [HEADER, "# socsim_cmd, SOCSIM_BUILD_RULES and SOCSIM_SYSTEM_*: cosim/soc/socsim.mk's.", ""]
    for ident, (system, ram_kib, flags, trace, baud, usb, proj_unit) in socs.items():
        top = (f"$(SOCSIM_SYSTEM_{system})" + (" --trace-fst" if trace else "") + (f" -GBAUD={baud}" if baud else "")
               + (" $(SOCSIM_USB_PARAMS)" if usb else "") + ("" if proj_unit else " -GPROJ_UNIT=0"))
        cflags = (f"$(SOCSIM_CFLAGS_{system})" + (" -DSOCSIM_TRACE=1" if trace else "")
                  + (f" -DSOCSIM_UART_BAUD={baud}" if baud else "") + (" $(SOCSIM_USB_CFLAGS)" if usb else ""))
        lines.append(f"SOCSIM_CMD_{ident} = $(call socsim_cmd,$(BUILD)/{ident},{top},{ram_kib * 1024},{flags},"
                     f"$(SOCSIM_SOURCES_{system}),{cflags})")
        lines.append(f"$(eval $(call SOCSIM_BUILD_RULES,$(BUILD)/{ident},SOCSIM_CMD_{ident},$(SOCSIM_PREREQS_{system})))")
    return "\n".join(lines) + "\n"


def gpusim_lists(table):
    lists = {}
    for family, spec in table.get("gpusim", {}).items():
        if "list" in spec:
            lists[spec["list"]] = [i for i, _ in expand(family, spec.get("params", {}))]
    return lists


# ---- firmware -----------------------------------------------------------------------------------
def fw_variants(table):
    out = {}
    for family, spec in table.get("fw_variant", {}).items():
        where = f"{BUILDS}: fw_variant.{family}"
        if spec.get("backend") not in ("fixed", "float"):
            raise TableError(f"{where}: backend = {spec.get('backend')!r}: fixed or float")
        lists = {k: v for k, v in spec.items() if k not in ("backend", "defs")}
        for k in lists:
            if "{" + k + "}" not in spec.get("defs", ""):
                raise TableError(f"{where}: unknown key {k} (a list-valued key is a {{{k}}} of defs)")
        for ident, values in expand(family, lists):
            out[ident] = (spec["backend"], spec.get("defs", "").format_map({k: str(v) for k, v in values.items()}))
    return out


def as_list(v):
    return v if isinstance(v, list) else [v]


def scene_set(value, boot, all_scenes, where):
    """A row's set as make's FW_ELF_RULES takes it: "", "one", "all", or a list of scenes joined by
    '+' (keys 1..N choose among them, in the list's order; the boot scene among them)."""
    if isinstance(value, list):
        for s in value:
            if s not in all_scenes:
                raise TableError(f"{where}: set: {s} is not in {SCENE_TABLE}")
        if boot not in value or len(set(value)) != len(value):
            raise TableError(f"{where}: set: the scenes once each, {boot} among them")
        return "+".join(value)
    if value not in ("", "one", "all"):
        raise TableError(f"{where}: set: one, all or a list of scenes, not {value!r}")
    return value


def fw_programs(table, variants):
    """Families: id -> (make condition or None, [program]); a program is a dict of its row's values.
    The condition: the family's platform (FW_PLATFORM) and, if given, its memory (SOC_MEM)."""
    all_scenes = scenes()
    out = {}
    seen = {}  # (kind, path) -> its settings: one path, one program, whichever families list it
    for family, spec in table.get("fw", {}).items():
        unknown = set(spec) - {"build", "platform", "memory"}
        if unknown:
            raise TableError(f"{BUILDS}: fw.{family}: unknown key {sorted(unknown)[0]}")
        rows = []
        for n, row in enumerate(spec.get("build", [])):
            where = f"{BUILDS}: fw.{family}.build[{n}]"
            unknown = set(row) - FW_ROW_KEYS
            if unknown:
                raise TableError(f"{where}: unknown key {sorted(unknown)[0]}")
            if "elf" not in row and "host" not in row:
                raise TableError(f"{where}: neither elf nor host")
            for key in ("scene", "variant", "frames"):
                if key not in row:
                    raise TableError(f"{where}: {key} missing")
            row_scenes = all_scenes if row["scene"] == "*" else as_list(row["scene"])
            for s in row_scenes:
                if "$(" not in s and s not in all_scenes:
                    raise TableError(f"{where}: scene {s} is not in {SCENE_TABLE}")
            for s, v in itertools.product(row_scenes, as_list(row["variant"])):
                if v not in variants:
                    raise TableError(f"{where}: variant {v} is not a fw_variant")
                suffix = "" if v == "fixed" else "-float" if v == "float" else f"-{v}"
                fill = {"scene": s, "variant": v, "suffix": suffix}
                prog = {"scene": s, "variant": v, "frames": str(row["frames"]),
                        "polls": str(row.get("polls", "")), "defs": row.get("defs", ""),
                        "set": scene_set(row.get("set", ""), s, all_scenes, where), "list": row.get("list", "")}
                for kind in ("elf", "host"):
                    if kind in row:
                        path = row[kind].format_map(fill)
                        key = (kind, path)
                        same = {k: prog[k] for k in ("scene", "variant", "frames", "polls", "defs", "set")}
                        if key in seen and seen[key] != same:
                            raise TableError(f"{where}: {path} is also built with other settings")
                        prog[kind] = path
                        seen[key] = same
                rows.append(prog)
        if "memory" in spec and "platform" not in spec:
            raise TableError(f"{BUILDS}: fw.{family}: memory without a platform")
        where_built = None
        if "platform" in spec:
            where_built = (f"$(FW_PLATFORM)/$(SOC_MEM)", f"{spec['platform']}/{spec['memory']}") \
                if "memory" in spec else ("$(FW_PLATFORM)", spec["platform"])
        out[family] = (where_built, rows)
    return out


# ---- the generated make ---------------------------------------------------------------------------
HEADER = "# Generated by mk/gen_builds.py from mk/builds.toml: do not edit.\n"


def builds_mk(table, sims, socs):
    lines = [HEADER]
    lim = load(CONTRACT)["limits"]
    lines.append("# The contract's frames, WxH: its default and its largest (make's FB=, make stress).")
    lines.append(f"CONTRACT_FB := {lim['fb_width']}x{lim['fb_height']}")
    lines.append(f"CONTRACT_FB_MAX := {lim['fb_max_width']}x{lim['fb_max_height']}")
    lines.append("# The largest buffer capacities: what the vertex and index windows hold.")
    lines += [f"CONTRACT_{k}_MAX := {v}" for k, v in cap_maxima().items()]
    lines.append(f"GPUSIM_IDS := {' '.join(sims)}")
    lines.append(f"SOCSIM_IDS := {' '.join(socs)}")
    lines += [f"SOCSIM_RAM_KIB_{i} := {ram}" for i, (_, ram, *_) in socs.items()]
    for name, ids in gpusim_lists(table).items():
        lines.append(f"{name} := {' '.join(f'$(BUILD)/{i}/gpusim' for i in ids)}")
    return "\n".join(lines) + "\n"


def gpusim_mk(sims):
    lines = [HEADER, "# $(call verilate,OUTPUT,FLAGS[,TOP,CFLAGS]) and SIM_DEPS: the Makefile's.", ""]
    for ident, (flags, display, trace) in sims.items():
        lines.append(f"$(BUILD)/{ident}/gpusim: $(SIM_DEPS)")
        top, cflags = ("gpu_core", ["-DGPUSIM_FAST_DISPLAY=1"]) if display == "fast" else ("", [])
        cflags += ["-DGPUSIM_TRACE=1"] if trace else []
        args = f",{top},{' '.join(cflags)}" if top or cflags else ""
        lines.append(f"\t$(call verilate,$@,{flags}{args})")
        lines.append("")
    return "\n".join(lines)


def firmware_mk(variants, families):
    lines = [HEADER, "# FW_BACKEND_RULES, FW_ELF_RULES and FW_HOST_RULES: firmware/firmware.mk's.", ""]
    lines.append(f"FW_VARIANTS := {' '.join(variants)}")
    for v, (backend, defs) in variants.items():
        lines.append(f"FW_BACKEND_DEFS_{v} := $(FW_BACKEND_DEFS_{backend}_BASE)")
        lines.append(f"FW_VARIANT_DEFS_{v} := {defs}")
    lines.append("$(foreach v,$(FW_VARIANTS),$(eval $(call FW_BACKEND_RULES,$(v))))")
    lists = {}
    done = set()  # a program two families of one platform list has its rules once
    for family, (platform, progs) in families.items():
        lines += ["", f"# fw.{family}"]
        if platform:
            lines.append(f"ifeq ({platform[0]},{platform[1]})")
        for p in progs:
            lst = p["list"]
            if lst:
                lists.setdefault(lst, None)
            for kind in ("elf", "host"):
                if kind not in p:
                    continue
                if (platform, kind, p[kind]) not in done:
                    done.add((platform, kind, p[kind]))
                    if kind == "elf":
                        args = [p["elf"], p["scene"], p["variant"], p["frames"], p["polls"], p["defs"], p["set"]]
                        lines.append(f"$(eval $(call FW_ELF_RULES,{','.join(args)}))")
                    else:
                        args = [p["host"], p["scene"], p["variant"], p["frames"], p["defs"]]
                        lines.append(f"$(eval $(call FW_HOST_RULES,{','.join(args)}))")
                if lst:
                    kinds = "ELFS" if kind == "elf" else "HOSTS"
                    lines.append(f"{lst}_{kinds} += {p[kind]}")
                    lines.append(f"{lst} += {p[kind]}")
            if lst:
                lines.append(f"{lst}_SCENES += {p['scene']}")
        if platform:
            lines.append("endif")
    init = [f"{l}_ELFS :=\n{l}_HOSTS :=\n{l} :=\n{l}_SCENES :=" for l in lists]
    lines[3:3] = init
    lines.append("")
    lines += [f"{l}_SCENES := $(sort $({l}_SCENES))" for l in lists]
    return "\n".join(lines) + "\n"


# ---- suites ---------------------------------------------------------------------------------------
def suites(table, sims, socs, families):
    data = load(SUITES)
    out = []
    kinds = (sims, socs, families, table.get("target", {}))
    ids = set().union(*kinds)
    for ident in ids:
        if sum(ident in k for k in kinds) > 1:
            raise TableError(f"{BUILDS}: {ident} names two builds (a simulator, a firmware family or a target)")
    for name, spec in data.get("suite", {}).items():
        where = f"{SUITES}: suite.{name}"
        unknown = set(spec) - {"cost", "needs", "run", "alone"}
        if unknown:
            raise TableError(f"{where}: unknown key {sorted(unknown)[0]}")
        if "run" not in spec:
            raise TableError(f"{where}: run missing")
        needs = list(spec.get("needs", []))
        for used in PLACEHOLDER.findall(spec["run"]):
            if used not in sims and used not in socs:
                raise TableError(f"{where}: {{{used}}} is not a simulator of {BUILDS}")
            if used not in needs:
                needs.append(used)
        for n in needs:
            if n not in ids:
                raise TableError(f"{where}: needs {n}, which {BUILDS} does not name")
        out.append((name, spec.get("cost", 30), bool(spec.get("alone", False)), needs, spec["run"]))
    return out


def target_of(ident, table, sims, socs, families):
    if ident in sims:
        return f"$(BUILD)/{ident}/gpusim"
    if ident in socs:
        return f"$(BUILD)/{ident}/socsim"
    if ident in table.get("target", {}):
        return table["target"][ident]
    platform, progs = families[ident]
    if all(p["list"] for p in progs):
        return " ".join(dict.fromkeys(f"$({p['list']})" for p in progs))
    paths = []
    for p in progs:
        paths += [p[k] for k in ("elf", "host") if k in p]
    return " ".join(dict.fromkeys(paths))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out")
    ap.add_argument("--needs")
    ap.add_argument("--suites", action="store_true")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--stats", action="store_true")
    args = ap.parse_args()
    try:
        table = load(BUILDS)
        sims = gpusims(table)
        socs = socsims(table)
        variants = fw_variants(table)
        families = fw_programs(table, variants)
        suite_list = suites(table, sims, socs, families)
    except (TableError, manifest.ManifestError) as e:
        print(f"gen_builds: {e}", file=sys.stderr)
        return 1
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        for name, text in (("builds.mk", builds_mk(table, sims, socs)), ("gpusim.mk", gpusim_mk(sims)),
                           ("socsim.mk", socsim_mk(socs)),
                           ("firmware.mk", firmware_mk(variants, families))):
            path = os.path.join(args.out, name)
            old = open(path).read() if os.path.exists(path) else None
            if old != text:
                with open(path, "w") as f:
                    f.write(text)
    if args.needs is not None:
        globs = args.needs.split() or ["*"]
        targets = []
        for name, _, _, needs, _ in suite_list:
            if any(fnmatch.fnmatchcase(name, g) for g in globs):
                targets += [target_of(n, table, sims, socs, families) for n in needs]
        print(" ".join(dict.fromkeys(targets)))
    if args.suites:
        for name, cost, alone, _, run in suite_list:
            cmd = PLACEHOLDER.sub(lambda m: f'"$BUILD/{m.group(1)}/'
                                  f'{"socsim" if m.group(1) in socs else "gpusim"}"', run)
            print(f"{'suite_alone' if alone else 'suite'} {name} {cost} {cmd}")
    if args.stats:
        progs = sum(len({p.get('elf') for p in ps if 'elf' in p}) + len({p.get('host') for p in ps if 'host' in p})
                    for _, ps in families.values())
        print(f"builds: {len(sims)} GPU simulators, {len(socs)} SoC simulators, {len(variants)} firmware object variants, "
              f"{progs} firmware programs in {len(families)} families, {len(suite_list)} suites")
    if args.check:
        print(f"gen_builds: {BUILDS} and {SUITES} valid")
    return 0


if __name__ == "__main__":
    sys.exit(main())

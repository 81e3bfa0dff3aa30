"""Finding worlds, models, meshes and plugins: resource paths, `model://` and `package://`.

Worlds and models are searched in the folders of MUJOCO_SIM_RESOURCE_PATH and of Gazebo's
variables (GZ_SIM_RESOURCE_PATH; the older IGN_GAZEBO_RESOURCE_PATH; classic Gazebo's
GAZEBO_MODEL_PATH and GAZEBO_RESOURCE_PATH, whose worlds are in a `worlds` subfolder), in
that order. `model://NAME` is the folder NAME in one of them, holding `model.config`, whose
`<sdf version="…">` (the highest version launcher reads), `<mjcf>` or `<urdf>` element names
the model file (Gazebo's layout); `model://sun` and `model://ground_plane` fall back on
built-in equivalents. `package://pkg/…` resolves through the package index.
A Gazebo Fuel URL (`https://fuel.gazebosim.org/1.0/OWNER/models/NAME[/VERSION]`) is looked up
in the local Fuel cache, as gz-fuel-tools keeps it (GZ_FUEL_CACHE_PATH, else ~/.gz/fuel:
HOST/OWNER/models/NAME/VERSION/, names in any case, the highest version unless one is given):
there is no network to fetch it from.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from collections.abc import Mapping
from pathlib import Path

from launcher.errors import LaunchError, did_you_mean

RESOURCE_PATH = "MUJOCO_SIM_RESOURCE_PATH"
RESOURCE_VARIABLES = (RESOURCE_PATH, "GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH",
                      "GAZEBO_MODEL_PATH", "GAZEBO_RESOURCE_PATH")
BUILTIN_WORLDS = Path(__file__).resolve().parent.parent / "builtin" / "mujoco_sim" / "worlds"
BUILTIN_MODELS = BUILTIN_WORLDS.parent / "models"  # model://sun, model://ground_plane
SDF_VERSIONS = ((1, 4), (1, 11))
WORLD_SUFFIXES = ("", ".sdf", ".world", ".xml", ".xml.j2")


FUEL_CACHE_VARIABLES = ("GZ_FUEL_CACHE_PATH", "IGN_FUEL_CACHE_PATH")


class ResourceNotFound(LaunchError):
    pass


def resource_entries(environ: Mapping[str, str] | None = None) -> list[tuple[Path, str]]:
    """Each resource folder with the variable it came from, in search order, once each."""
    env = os.environ if environ is None else environ
    found: list[tuple[Path, str]] = []
    for variable in RESOURCE_VARIABLES:
        for part in env.get(variable, "").split(os.pathsep):
            folder = Path(part).expanduser() if part else None
            if folder is not None and all(folder != f for f, _ in found):
                found.append((folder, variable))
    return found


def resource_dirs(environ: Mapping[str, str] | None = None) -> list[Path]:
    return [folder for folder, _ in resource_entries(environ)]


def find_world(name: str, environ: Mapping[str, str] | None = None) -> Path:
    """A world as a path, then in each resource folder, then among the built-in worlds."""
    env = os.environ if environ is None else environ
    candidate = Path(name).expanduser()
    if candidate.exists() and not candidate.is_dir():  # (a FIFO too: refused when read)
        return candidate.resolve()
    searched = [f"the path {candidate.resolve()}"]
    if not candidate.is_absolute():
        for folder, variable in resource_entries(env):
            places = [folder, folder / "worlds"] if variable == "GAZEBO_RESOURCE_PATH" \
                else [folder]
            for place in places:
                for suffix in WORLD_SUFFIXES[:3]:  # `gz sim shapes` finds shapes.sdf
                    if (place / f"{name}{suffix}").is_file():
                        return (place / f"{name}{suffix}").resolve()
            searched.append(f"{folder} ({variable})")
        # classic Gazebo's `worlds/empty.world` is the built-in empty world
        for stem in dict.fromkeys((name, Path(name).name, Path(name).stem)):
            for suffix in WORLD_SUFFIXES:
                if (BUILTIN_WORLDS / f"{stem}{suffix}").is_file():
                    return BUILTIN_WORLDS / f"{stem}{suffix}"
        searched.append(f"the built-in worlds ({', '.join(builtin_worlds())})")
    values = "; ".join(f"{v}={env[v]!r}" if env.get(v) else f"{v} is not set"
                       for v in RESOURCE_VARIABLES)
    known = [p.name for d in resource_dirs(env) if d.is_dir() for p in d.iterdir()]
    raise ResourceNotFound(f"world '{name}' not found; searched:\n  " + "\n  ".join(searched)
                           + f"\n  ({values})" + did_you_mean(name, known + builtin_worlds()))


def builtin_worlds() -> list[str]:
    return sorted(p.name for p in BUILTIN_WORLDS.iterdir() if p.is_file())


def find_model(name: str, environ: Mapping[str, str] | None = None) -> Path:
    """The folder of `model://NAME`: in a resource folder, else one of Gazebo's common models
    launcher has built in (sun, ground_plane)."""
    entries = resource_entries(environ)
    for folder, _ in entries:
        if (folder / name).is_dir():
            return folder / name
    if (BUILTIN_MODELS / name).is_dir():
        return BUILTIN_MODELS / name
    where = ", ".join(f"{f} ({v})" for f, v in entries) or \
        f"nowhere: none of {', '.join(RESOURCE_VARIABLES)} is set"
    known = [p.name for f, _ in entries if f.is_dir() for p in f.iterdir() if p.is_dir()]
    raise ResourceNotFound(f"model '{name}' (model://{name}) not found; searched: "
                           f"{where}{did_you_mean(name, known)}")


def model_file(folder: Path) -> Path:
    """The model file a model folder's model.config names (or its only model file)."""
    config = folder / "model.config"
    if not config.is_file():
        found = sorted(p for p in folder.iterdir() if p.suffix in (".xml", ".urdf", ".sdf"))
        if len(found) == 1:
            return found[0]
        raise ResourceNotFound(f"model folder {folder} has no model.config")
    try:
        root = ET.parse(config).getroot()
    except ET.ParseError as exc:
        raise LaunchError(f"{config}:{exc.position[0]}:{exc.position[1] + 1}: "
                          f"model.config is not valid XML: {exc}") from None
    chosen = _sdf_entry(root, config)
    if chosen is None:
        chosen = next((e for tag in ("mjcf", "urdf") for e in root.findall(tag)
                       if (e.text or "").strip()), None)
    if chosen is None:
        raise LaunchError(f"{config}: no usable model file: expected <sdf version=\"1.x\">"
                          "model.sdf</sdf> (or <mjcf>/<urdf>) naming the model file")
    path = folder / (chosen.text or "").strip()
    if not path.is_file():
        raise ResourceNotFound(f"{config}: <{chosen.tag}> names '{(chosen.text or '').strip()}'"
                               f", which is not in {folder}")
    return path


def _sdf_entry(root: ET.Element, config: Path) -> ET.Element | None:
    """The `<sdf>` entry of the highest version launcher reads; none is usable is an error."""
    entries = [e for e in root.findall("sdf") if (e.text or "").strip()]
    usable = []
    for entry in entries:
        major, _, minor = entry.get("version", "1.4").strip().partition(".")
        version = (int(major), int(minor)) if major.isdigit() and minor.isdigit() else None
        if version is not None and SDF_VERSIONS[0] <= version <= SDF_VERSIONS[1]:
            usable.append((version, entry))
    if usable:
        return max(usable, key=lambda pair: pair[0])[1]
    if entries:
        offered = ", ".join(f"{e.get('version', '?')} ({(e.text or '').strip()})"
                            for e in entries)
        raise LaunchError(f"{config}: no <sdf> entry launcher can read: offered {offered}; "
                          "launcher reads SDF 1.4 to 1.11")
    return None


def fuel_caches(environ: Mapping[str, str] | None = None) -> list[tuple[Path, str]]:
    """The local Fuel caches, each with where it came from."""
    env = os.environ if environ is None else environ
    for variable in FUEL_CACHE_VARIABLES:
        if env.get(variable):
            return [(Path(env[variable]).expanduser(), variable)]
    home = Path(env.get("HOME", "~")).expanduser()
    return [(home / ".gz" / "fuel", "the default"), (home / ".ignition" / "fuel", "the default")]


def find_fuel_model(uri: str, environ: Mapping[str, str] | None = None) -> Path:
    """The cached folder of a Fuel model URL (or the file it names below the model)."""
    host, _, path = uri.split("://", 1)[1].partition("/")
    parts = [p for p in path.split("/") if p]
    if len(parts) < 4 or parts[2].lower() != "models":
        raise ResourceNotFound(f"'{uri}' is not a Fuel model URL (https://HOST/1.0/OWNER/"
                               "models/NAME)")
    owner, name, rest = parts[1], parts[3], parts[4:]
    version = rest.pop(0) if rest and (rest[0].isdigit() or rest[0] == "tip") else None
    if rest[:1] == ["files"]:
        rest = rest[1:]
    searched = []
    for cache, origin in fuel_caches(environ):
        folder = _case_blind(cache, [host, owner, "models", name])
        searched.append(f"{cache / host / owner.lower() / 'models' / name.lower()} ({origin})")
        versions = sorted((int(v.name) for v in folder.iterdir() if v.name.isdigit()),
                          reverse=True) if folder is not None and folder.is_dir() else []
        chosen = versions[:1] if version in (None, "tip") else \
            [int(version)] if int(version) in versions else []
        if chosen:
            found = folder / str(chosen[0])  # type: ignore[operator]
            return found.joinpath(*rest) if rest else model_file(found)
    raise ResourceNotFound(
        f"'{uri}' is not in the local Fuel cache, and models are not fetched from the network"
        f"; searched: {', '.join(searched)}. Put the model there (a folder per version, "
        "holding model.config and the model file), or in a folder on GZ_SIM_RESOURCE_PATH "
        "and include it as model://NAME")


def _case_blind(root: Path, names: list[str]) -> Path | None:
    """root/names…, each name matched in any case (Fuel keeps them lower-cased)."""
    folder = root
    for name in names:
        if not folder.is_dir():
            return None
        exact = folder / name
        if exact.is_dir():
            folder = exact
            continue
        match = next((p for p in folder.iterdir() if p.name.lower() == name.lower()), None)
        if match is None:
            return None
        folder = match
    return folder


def resolve_uri(uri: str, base: Path | None, packages: object | None = None,
                environ: Mapping[str, str] | None = None) -> Path:
    """A file for a mesh or model URI: package://, model://, file://, a Fuel URL, absolute or
    relative."""
    if uri.startswith(("http://", "https://")):
        return find_fuel_model(uri.strip(), environ).resolve()
    if uri.startswith("package://"):
        package, _, rest = uri[len("package://"):].partition("/")
        if packages is None:
            from launcher.packages.index import PackageIndex

            packages = PackageIndex.from_environment(environ)
        try:
            root = packages.share(package)  # type: ignore[attr-defined]
        except LaunchError as exc:
            raise ResourceNotFound(f"'{uri}': {exc}") from None
        path = Path(root) / rest
        where = f"package '{package}' at {root}"
    elif uri.startswith("model://"):
        name, _, rest = uri[len("model://"):].partition("/")
        folder = find_model(name, environ)
        path = folder / rest if rest else model_file(folder)
        where = f"model folder {folder}"
    else:
        raw = uri[len("file://"):] if uri.startswith("file://") else uri
        path = Path(raw).expanduser()
        if not path.is_absolute():
            path = (base or Path.cwd()) / path
        where = f"{path.parent}"
    if not path.exists():
        raise ResourceNotFound(f"'{uri}' not found: looked for {path} (in {where})")
    return path.resolve()

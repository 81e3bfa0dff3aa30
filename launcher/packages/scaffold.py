"""`launcher pkg create NAME`: a new package from the templates in `skeleton/`.

The package gets package.xml (with its dependencies and a Python entry point), an example
environment hook `hooks/NAME.dsv.in`, `launch/NAME.launch.yaml`, and a Python node.
"""

from __future__ import annotations

import getpass
from pathlib import Path

import jinja2

from launcher.errors import UsageError
from launcher.packages.manifest import NAME_RULE

SKELETON = Path(__file__).resolve().parent / "skeleton"


def create_package(name: str, destination: str, dependencies: list[str],
                   description: str) -> Path:
    if not NAME_RULE.match(name):
        raise UsageError(f"invalid package name '{name}': use lowercase letters, digits and "
                         "underscores, starting with a letter")
    for dependency in dependencies:
        if not NAME_RULE.match(dependency):
            raise UsageError(f"invalid dependency name '{dependency}'")
    folder = Path(destination) / name
    if folder.exists():
        raise UsageError(f"'{folder}' already exists; choose another name or destination")
    environment = jinja2.Environment(loader=jinja2.FileSystemLoader(SKELETON),
                                     undefined=jinja2.StrictUndefined, keep_trailing_newline=True,
                                     trim_blocks=True, lstrip_blocks=True, autoescape=False)
    values = {"name": name, "description": description, "dependencies": dependencies,
              "maintainer": getpass.getuser(), "email": f"{getpass.getuser()}@localhost"}
    for template in sorted(SKELETON.rglob("*")):
        if not template.is_file():
            continue
        relative = template.relative_to(SKELETON).as_posix()
        target = folder / relative.replace("NAME", name).replace("module/", f"{name}/") \
            .removesuffix(".j2")
        target.parent.mkdir(parents=True, exist_ok=True)
        if template.name == ".keep":
            continue
        target.write_text(environment.get_template(relative).render(values))
    return folder

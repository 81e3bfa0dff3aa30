"""`package.xml` (REP 149, formats 1–3): the parts launcher uses."""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

from launcher.errors import Location, ParseError
from launcher.records import dataclass, field

NAME_RULE = re.compile(r"^[a-z][a-z0-9_]*$")
# Build types whose executables and libraries exist only once built (colcon, catkin)
COMPILED_BUILD_TYPES = ("ament_cmake", "cmake", "catkin")
DEPENDENCY_TAGS = ("depend", "build_depend", "build_export_depend", "buildtool_depend",
                   "buildtool_export_depend", "exec_depend", "run_depend", "test_depend",
                   "doc_depend")


@dataclass(eq=False)
class Package:
    name: str
    path: Path  # the package folder: $(find-pkg-share) for packages used in place
    version: str = ""
    description: str = ""
    maintainers: list[str] = field(default_factory=list)
    licenses: list[str] = field(default_factory=list)
    dependencies: dict[str, list[str]] = field(default_factory=dict)  # tag -> names
    exports: dict[str, list[dict[str, str]]] = field(default_factory=dict)  # tag -> attrs
    prefix: Path | None = None  # an install prefix, for packages from AMENT_PREFIX_PATH
    origin: str = "workspace"  # workspace | checkout | builtin | ament
    # launcher's own implementation of it, for a compiled package found only as source
    stand_in: Package | None = None

    @property
    def manifest(self) -> Path:
        return self.path / "package.xml"

    @property
    def build_type(self) -> str:
        """package.xml's `<build_type>`; a package without one but with a CMakeLists.txt is
        built by CMake (ament_cmake, as colcon takes it)."""
        declared = self.exports.get("build_type", [])
        if declared:
            return declared[0]["text"]
        return "ament_cmake" if (self.path / "CMakeLists.txt").is_file() else ""

    @property
    def compiled(self) -> bool:
        return self.build_type in COMPILED_BUILD_TYPES

    def run_dependencies(self) -> set[str]:
        tags = ("depend", "exec_depend", "run_depend", "build_export_depend")
        return {name for tag in tags for name in self.dependencies.get(tag, [])}


def read_manifest(path: Path, origin: str = "workspace") -> Package:
    """Parse `path` (a package.xml); errors name the file and line."""
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as exc:
        line, column = exc.position
        reason = re.sub(r": line \d+, column \d+$", "", str(exc))
        raise ParseError(f"malformed package.xml: {reason}",
                         Location(str(path), line, column + 1)) from None
    except OSError as exc:
        raise ParseError(f"cannot read package.xml: {exc.strerror}", Location(str(path))) \
            from None
    if root.tag != "package":
        raise ParseError(f"the root element is <{root.tag}>; expected <package>",
                         Location(str(path), 1))
    name = (root.findtext("name") or "").strip()
    if not name:
        where = Location(str(path), _line_of(path, "<package"))
        raise ParseError("package.xml has no <name>", where)
    if not NAME_RULE.match(name):
        raise ParseError(
            f"invalid package name '{name}': names start with a lowercase letter and hold only "
            "lowercase letters, digits and underscores", Location(str(path),
                                                                  _line_of(path, "<name")))
    package = Package(
        name=name, path=path.parent, origin=origin,
        version=(root.findtext("version") or "").strip(),
        description=" ".join((root.findtext("description") or "").split()),
        maintainers=[(m.text or "").strip() for m in root.findall("maintainer")],
        licenses=[(m.text or "").strip() for m in root.findall("license")],
    )
    for tag in DEPENDENCY_TAGS:
        names = [(d.text or "").strip() for d in root.findall(tag) if (d.text or "").strip()]
        if names:
            package.dependencies[tag] = names
    export = root.find("export")
    if export is not None:
        for child in export:
            package.exports.setdefault(child.tag, []).append(
                {**child.attrib, "text": (child.text or "").strip()})
    return package


def _line_of(path: Path, needle: str) -> int:
    try:
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if needle in line:
                return number
    except OSError:
        pass
    return 0

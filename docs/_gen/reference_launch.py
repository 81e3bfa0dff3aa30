"""The launch-file reference: every action (tag) and substitution, with the fields each
declares and their docs, from the registry the frontends look tags up in."""

from __future__ import annotations

from collections import defaultdict

from md_tables import code, table

from launcher import records
from launcher.description.registry import Registry
from launcher.schema import Kind, declared_fields, frontend_name

TITLE = """# Launch files

Every tag of the YAML and XML formats, and every substitution, as the registry declares them
(generated at each build). Every tag also takes `if` or `unless` (true, false, 1 or 0). In
Python launch files the same actions are `launcher.api`'s (and `launch`'s and `launch_ros`'s)
classes, with these fields as keyword arguments.
"""

KINDS = {Kind.TEXT: "text", Kind.NAME: "name", Kind.BOOL: "bool", Kind.FLOAT: "number",
         Kind.INT: "integer", Kind.COMMAND: "command line", Kind.ENTRIES: "list of entries",
         Kind.ACTIONS: "actions", Kind.CHILDREN: "actions", Kind.NAMES: "list of names",
         Kind.VALUE: "value"}


def page() -> str:
    registry = Registry()
    registry.load_all()
    parts = [TITLE, "## Tags\n"]
    for tags, cls in _grouped(registry.actions):
        parts.append(_action(tags, cls))
    parts.append("## Substitutions\n")
    rows = [(", ".join(code(_usage(n, cls)) for n in names), _first_paragraph(cls.__doc__))
            for names, cls in _grouped(registry.substitutions)]
    parts.append(table(("substitution", "what it gives"), rows))
    return "\n".join(parts)


def _grouped(found: dict[str, type]) -> list[tuple[list[str], type]]:
    """Each class once, with every name it answers to (sorted by its first name)."""
    names: dict[type, list[str]] = defaultdict(list)
    for name, cls in found.items():
        names[cls].append(name)
    return sorted(((sorted(n), cls) for cls, n in names.items()), key=lambda item: item[0][0])


def _action(tags: list[str], cls: type) -> str:
    title = " / ".join(f"`{tag}`" for tag in tags)
    out = [f"### {title}\n"]
    doc = _first_paragraph(cls.__doc__)
    if doc:
        out.append(doc + "\n")
    rows = []
    for field, spec in declared_fields(cls):
        name = frontend_name(field, spec)
        aliases = f" (or {', '.join(code(a) for a in spec.aliases)})" if spec.aliases else ""
        kind = KINDS[spec.kind]
        if spec.entry is not None:
            entry = ", ".join(frontend_name(f, s) for f, s in declared_fields(spec.entry))
            kind += f": {entry}"
        if spec.choices:
            kind += ": " + ", ".join(spec.choices)
        default = field.default if not callable(getattr(field, "default_factory", None)) \
            else None
        shown = "required" if spec.required else code(default) if _shown(default) else ""
        rows.append((code(name) + aliases, kind, shown, spec.doc))
    out.append(table(("attribute", "kind", "default", "meaning"), rows) if rows else
               "No attributes.\n")
    return "\n".join(out)


def _usage(name: str, cls: type) -> str:
    """`$(name ARG [OPTIONAL])`, from the fields `$(…)`'s words are mapped onto."""
    words = []
    for field in records.fields(cls):
        if not field.init or field.kw_only:
            continue
        word = field.name.upper()
        if field.default == ():  # as many as given
            words.append(f"{word.removesuffix('S')}…")
        else:
            words.append(word if field.default is records.MISSING else f"[{word}]")
    return f"$({' '.join([name, *words])})"


def _shown(default: object) -> bool:
    return default is not None and default != "" and not repr(default).startswith("<")


def _first_paragraph(doc: str | None) -> str:
    if not doc:
        return ""
    return " ".join(doc.strip().split("\n\n")[0].split())

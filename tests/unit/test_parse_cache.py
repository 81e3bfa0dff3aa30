"""Parsed launch files kept between runs (frontend/parse_cache.py)."""

from __future__ import annotations

import os
import stat

import pytest

from launcher.frontend import loader, parse_cache

LAUNCH = """launch:
  - arg: {name: robot, default: "r1"}
  - executable: {cmd: "echo $(var robot)", name: talker, output: screen}
  - group:
      - executable: {cmd: "sleep 1"}
"""


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("LAUNCHER_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(loader, "_cache", {})  # the in-process cache of descriptions
    return tmp_path / "cache" / "parsed"


def entity_text(entity) -> str:
    """The tree, with every place, as text to compare."""
    attributes = {name: (entity_text_all(a.value) if isinstance(a.value, list) else a.value,
                         tuple(a.location), a.text_offset, a.key_location)
                  for name, a in entity.attributes.items()}
    return repr((entity.tag, tuple(entity.location), attributes,
                 [entity_text(c) for c in entity.children], entity.nested_in_children))


def entity_text_all(entities) -> list[str]:
    return [entity_text(e) for e in entities]


@pytest.mark.parametrize("name, text", [
    ("a.launch.yaml", LAUNCH),
    ("a.launch.xml", '<launch><arg name="robot" default="r1"/>\n'
                     '<executable cmd="echo $(var robot)"><env name="A" value="1"/></executable>'
                     '</launch>'),
])
def test_a_second_load_gives_the_same_tree_without_the_parser(cache, tmp_path, monkeypatch,
                                                               name, text):
    path = tmp_path / name
    path.write_text(text)
    parsed = loader._parse(loader.launch_format(path), path.read_bytes(), path)
    loader.load_file(path)
    entries = list(cache.iterdir())
    assert len(entries) == 1
    assert stat.S_IMODE(cache.stat().st_mode) == 0o700
    assert stat.S_IMODE(entries[0].stat().st_mode) == 0o600  # it holds the launch file's text

    def no_parsing(*_args):
        raise AssertionError("parsed again")

    monkeypatch.setattr(loader, "_cache", {})
    monkeypatch.setattr(loader, "_parse", no_parsing)
    kept = parse_cache.get(path, path.read_bytes())
    assert kept is not None and entity_text(kept) == entity_text(parsed)
    assert loader.load_file(path).actions  # built from the kept tree


def test_a_changed_file_a_damaged_entry_or_an_open_folder_means_parsing_again(cache, tmp_path):
    path = tmp_path / "b.launch.yaml"
    path.write_text(LAUNCH)
    loader.load_file(path)
    assert parse_cache.get(path, path.read_bytes()) is not None
    assert parse_cache.get(path, path.read_bytes().replace(b"r1", b"r2")) is None  # other text
    entry = next(cache.iterdir())
    entry.write_bytes(b"\x00garbage")
    assert parse_cache.get(path, path.read_bytes()) is None
    parse_cache.put(path, path.read_bytes(), loader._parse(".yaml", path.read_bytes(), path))
    assert parse_cache.get(path, path.read_bytes()) is not None
    os.chmod(cache, 0o777)  # others could have written it: not read
    assert parse_cache.get(path, path.read_bytes()) is None


def test_an_error_is_not_kept_and_is_reported_every_time(cache, tmp_path):
    path = tmp_path / "bad.launch.yaml"
    path.write_text("launch:\n  - executable: {cmd: [unclosed\n")
    for _ in range(2):
        with pytest.raises(Exception, match="malformed YAML"):
            loader.load_file(path)
    assert not cache.exists() or not list(cache.iterdir())


def test_the_cache_keeps_to_its_size(cache, tmp_path, monkeypatch):
    monkeypatch.setattr(parse_cache, "MAX_ENTRIES", 4)
    for index in range(9):
        path = tmp_path / f"f{index}.launch.yaml"
        path.write_text(LAUNCH)
        loader.load_file(path)
    assert len(list(cache.iterdir())) <= 4

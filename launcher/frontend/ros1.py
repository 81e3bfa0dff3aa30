"""roslaunch's XML (ROS 1), told from ROS 2's XML by what a file says, and rewritten into the
entities launcher's actions take. Every place is kept as written, so errors point into the
user's file.

ROS 1 → launcher:
- `arg` with `default` → `arg`; with `value` (fixed, as roslaunch has it) → `let`; `doc` is
  its description.
- `node pkg type name ns args output respawn respawn_delay required launch-prefix cwd` → `node`
  (`type` is the executable, `required="true"` ends the launch when it exits); its `param`s
  and `rosparam`s are its private parameters, `remap`s and `env`s its own.
- `param` outside a node → `set_parameter` for the nodes after it in its scope (names resolve
  in the enclosing `ns`); `command=`, `textfile=` give its text.
- `rosparam command="load"` (a file, or YAML inside the tag; `param`, `ns`, `subst_value`);
  outside a node, `dump` writes the parameters set so far to a file and `delete` removes them
  for the nodes after it (a node's own `dump`/`delete` have nothing to act on and are dropped).
- `group ns` → `group` with `push_ros_namespace`; `include file ns pass_all_args` with `arg`
  children → `include` (its arguments kept apart, as roslaunch scopes them per file).
- `remap` and `env` outside a node → `set_remap`, `set_env` (scoped by `group`).
- `machine name address user ssh-port env-loader timeout default` → `roslaunch_machine`
  (a node's `machine=` names one; `password=`, `ros-*=` and `<env>` in it are refused); `test`
  is rostest's, which roslaunch does not run.
"""

from __future__ import annotations

import re

from launcher.description.actions.machine import DEFAULTS, password_refusal
from launcher.description.parameters import ROS1_TYPES
from launcher.errors import Location, ParseError, did_you_mean
from launcher.frontend.entity import Attribute, Entity

# What only ROS 1 says, and what only ROS 2 says (a tag, or an attribute of a tag).
ROS1_TAGS = {"rosparam": "<rosparam>", "test": "<test>"}  # (and <machine>: see dialect)
ROS2_TAGS = {"let", "set_env", "unset_env", "push_ros_namespace", "push-ros-namespace",
             "executable", "composable_node", "node_container", "load_composable_node",
             "set_parameter", "set_remap", "set_parameters_from_file", "set_use_sim_time",
             "for", "for_each", "timer", "log", "shutdown", "set_ros_log_dir"}
WARN = "[WARN] [launch]"


def dialect(root: Entity, default: str = "ros2") -> str:
    """'ros1' or 'ros2' for an XML launch tree (`default` when nothing tells: ROS 1 for a
    `.launch` file); a file that mixes them is an error naming a line of each. A file that
    opts in to launcher's extensions is a ROS 2 file; `<machine>` tells ROS 1 only when
    nothing tells ROS 2 (a ROS 2 file's is launcher's extension)."""
    ros1 = ros2 = machine = None
    extended = root.attributes.get("extensions")
    if extended is not None:
        ros2 = ("`extensions=` on <launch>", extended.location)
    for entity in _walk(root):
        if entity.tag == "machine":  # (a ROS 2 file's is launcher's: builder.py says so)
            machine = machine or ("<machine>", entity.location)
            continue
        one, two = _signs(entity)
        ros1 = ros1 or one
        ros2 = ros2 or two
    ros1 = ros1 or (None if ros2 else machine)
    if ros1 and ros2:
        raise ParseError(f"this file mixes roslaunch (ROS 1) and ROS 2 launch XML: "
                         f"{ros1[0]} at line {ros1[1].line} is ROS 1, {ros2[0]} at line "
                         f"{ros2[1].line} is ROS 2; write it in one of them", ros2[1])
    return "ros1" if ros1 else "ros2" if ros2 else default


def _walk(entity: Entity):
    yield entity
    for child in entity.children:
        yield from _walk(child)


def _signs(entity: Entity) -> tuple[tuple[str, Location] | None, tuple[str, Location] | None]:
    one = two = None
    attrs = entity.attributes
    if entity.tag in ROS1_TAGS:
        one = (ROS1_TAGS[entity.tag], entity.location)
    elif entity.tag == "node" and "type" in attrs:
        one = ("`type=` on <node>", entity.location)
    elif entity.tag == "param" and ({"command", "textfile", "binfile"} & set(attrs)):
        one = ("<param command=/textfile=>", entity.location)
    elif entity.tag == "include" and ({"pass_all_args", "clear_params"} & set(attrs)):
        one = ("<include pass_all_args/clear_params>", entity.location)
    elif entity.tag == "arg" and "doc" in attrs:
        one = ("`doc=` on <arg>", entity.location)
    if entity.tag in ROS2_TAGS:
        two = (f"<{entity.tag}>", entity.location)
    elif entity.tag == "node" and "exec" in attrs:
        two = ("`exec=` on <node>", entity.location)
    for attribute in attrs.values():
        text = attribute.value if isinstance(attribute.value, str) else ""
        if one is None and "$(arg " in text:
            one = ("$(arg …)", attribute.location)
        if two is None and "$(var " in text:
            two = ("$(var …)", attribute.location)
    return one, two


def translate(root: Entity) -> Entity:
    """The ROS 2 entity tree that does what this roslaunch tree does. (/run_id, /rosdistro
    and /rosversion: the parameter server holds them from its start, as a master does.)"""
    _unique_names(root.children, "", {})
    _args_once(root.children, {})
    _one_condition(root)
    out = Entity("launch", root.location, nested_in_children=True)
    _WARNINGS.clear()
    deprecated = root.attributes.get("deprecated")
    if deprecated is not None:  # roslaunch prints it, and goes on
        _WARNINGS.append(_warning(f"{root.location}: DEPRECATED: {deprecated.value}",
                                  deprecated.location))
    body = _body(root.children)
    out.children = [*_WARNINGS, *body]
    _WARNINGS.clear()
    for entity in _walk(out):  # their text is read by roslaunch's rules
        for attribute in entity.attributes.values():
            attribute.roslaunch = True
    return out


def _args_once(children: list[Entity], seen: dict[str, Location]) -> None:
    """roslaunch's loader: an arg is declared once in a file; a group sees what was declared
    before it, and what it declares is its own (the same name may be declared after it, or
    in another group); an include's file has its own."""
    for child in children:
        if child.tag == "arg":
            name = _literal(child, "name")
            # (one under if= or unless= may be declared again under the opposite condition,
            # as gazebo_ros's empty_world.launch does: roslaunch skips the one that is off)
            if name and not {"if", "unless"} & set(child.attributes):
                if name in seen:
                    raise ParseError(f"Invalid <arg> tag: arg '{name}' has already been "
                                     f"declared (at line {seen[name].line})", child.location)
                seen[name] = child.location
        elif child.tag == "group":
            _args_once(child.children, dict(seen))


def _one_condition(root: Entity) -> None:
    """xmlloader.ifunless_test: "cannot set both 'if' and 'unless' on the same tag"."""
    for entity in _walk(root):
        if "if" in entity.attributes and "unless" in entity.attributes:
            raise ParseError(f"<{entity.tag}> has both if= and unless=: roslaunch takes one "
                             "of them on a tag (nest a <group> for the other)",
                             entity.attributes["unless"].location)


def _literal(entity: Entity, name: str) -> str | None:
    attribute = entity.attributes.get(name)
    if attribute is None:
        return ""
    text = attribute.value if isinstance(attribute.value, str) else ""
    return None if "$(" in text else text


def _unique_names(children: list[Entity], space: str, seen: dict[str, Location]) -> None:
    """roslaunch refuses two nodes of one name before it starts anything: the same here for
    names written out (those made by substitutions are checked as the nodes start)."""
    for child in children:
        if "if" in child.attributes or "unless" in child.attributes:
            continue
        if child.tag == "group":
            ns = _literal(child, "ns")
            if ns is not None:
                _unique_names(child.children, _join(space, ns), seen)
        elif child.tag == "node":
            name, ns = _literal(child, "name"), _literal(child, "ns")
            if name and ns is not None:
                full = f"{_join(space, ns).rstrip('/')}/{name}"
                if full in seen:
                    raise ParseError(
                        f"roslaunch file contains multiple nodes named [{full}]. Please check "
                        "all <node> 'name' attributes to make sure they are unique. Also check "
                        f"that $(anon id) use different ids. (the other is at {seen[full]})",
                        child.location)
                seen[full] = child.location


def _join(outer: str, inner: str) -> str:
    if inner.startswith("/"):
        return inner.rstrip("/")
    return "/".join(p for p in (outer.strip("/"), inner.strip("/")) if p).join(("/", "")) \
        if (outer.strip("/") or inner.strip("/")) else ""


def _body(children: list[Entity]) -> list[Entity]:
    made: list[Entity] = []
    for child in children:
        made += _entity(child)
    return made


ENTRY_CONDITIONS = ("only_if", "only_unless")  # a node child's if= and unless=, as entries


def _copy(entity: Entity, tag: str, names: dict[str, str]) -> Entity:
    """`entity` as `tag`, its attributes renamed by `names` (old → new; others dropped)."""
    made = Entity(tag, entity.location, nested_in_children=True)
    for old, new in names.items():
        if old in entity.attributes:
            made.attributes[new] = entity.attributes[old]
    for condition in ("if", "unless", *ENTRY_CONDITIONS):
        if condition in entity.attributes:
            made.attributes[condition] = entity.attributes[condition]
    return made


_WARNINGS: list[Entity] = []  # what the translation of one file warns about (translate)


def _known(entity: Entity, allowed: set[str]) -> None:
    """An attribute roslaunch does not know is warned about and left out, as roslaunch's
    loader does (_check_attrs: a configuration error it prints, and goes on)."""
    for name, attribute in list(entity.attributes.items()):
        if name not in allowed | {"if", "unless", *ENTRY_CONDITIONS, "#text"}:
            hint = did_you_mean(name, allowed)
            _WARNINGS.append(_warning(
                f"{attribute.name_location}: roslaunch's <{entity.tag}> has no attribute "
                f"'{name}'{hint}; it is ignored, as roslaunch ignores it (it takes "
                f"{', '.join(sorted(allowed))})", attribute.name_location))
            del entity.attributes[name]


def _text(value: str, where: Location) -> Attribute:
    return Attribute(value, where)


def _entity(entity: Entity) -> list[Entity]:
    tag = entity.tag
    if tag == "arg":
        _known(entity, {"name", "default", "value", "doc"})
        if "value" in entity.attributes and "default" in entity.attributes:
            raise ParseError(f"<arg name='{_literal(entity, 'name')}'> has both value= and "
                             "default=: roslaunch takes one (value= fixes it, default= lets "
                             "the command line or an include set it)",
                             entity.attributes["default"].location)
        if "value" in entity.attributes:  # a constant: overriding it is roslaunch's error
            fixed = _copy(entity, "let", {"name": "name", "value": "value"})
            fixed.attributes["fixed"] = _text("true", entity.location)
            return [fixed]
        return [_copy(entity, "arg", {"name": "name", "default": "default",
                                      "doc": "description"})]
    if tag == "node":
        name = str(entity.attributes["name"].value) if "name" in entity.attributes else ""
        ns = str(entity.attributes["ns"].value).strip("/") if "ns" in entity.attributes else ""
        return [*_clearing(entity, f"{ns}/{name}" if ns and name else name), _node(entity)]
    if tag == "test":  # rostest runs it; roslaunch leaves it out (description/actions/rostest)
        return [_test(entity)]
    if tag == "param":
        return [_global_param(entity)]
    if tag == "rosparam":
        return _global_rosparam(entity)
    if tag == "group":
        _known(entity, {"ns", "clear_params"})
        _ns_given(entity)
        group = _copy(entity, "group", {})
        if "ns" in entity.attributes:
            push = Entity("push_ros_namespace", entity.location, nested_in_children=True)
            push.attributes["namespace"] = entity.attributes["ns"]
            group.children.append(push)
        group.children += [*_clearing(entity, ""), *_body(entity.children)]
        return [group]
    if tag == "include":
        return [_include(entity)]
    if tag == "remap":
        _known(entity, {"from", "to"})
        _remap_names(entity)
        return [_copy(entity, "set_remap", {"from": "from", "to": "to"})]
    if tag == "env":
        _known(entity, {"name", "value"})
        return [_copy(entity, "set_env", {"name": "name", "value": "value"})]
    if tag == "machine":
        return [_machine(entity)]
    return [_warning(f"{entity.location}: roslaunch has no tag <{tag}>; it is ignored, as "
                     "roslaunch ignores it (ROS 1's tags: arg, node, param, rosparam, group, "
                     "include, remap, env, machine, test)", entity.location)]


MACHINE_ATTRS = ("name", "address", "env-loader", "ssh-port", "user", "default", "timeout")
ROS_ATTRS = ("ros-root", "ros-package-path", "ros-ip", "ros-hostname")


def _machine(entity: Entity) -> Entity:
    """xmlloader._machine_tag's checks of what is written out (what substitutions make is
    checked as the machine is declared), at the attribute."""
    for name in ROS_ATTRS:
        if name in entity.attributes:
            raise ParseError("<machine>: ros-* attributes are not supported since ROS Fuerte. "
                             "Please use env-loader instead",
                             entity.attributes[name].name_location)
    password = entity.attributes.get("password")
    if password is not None:
        user, address = _literal(entity, "user"), _literal(entity, "address")
        raise ParseError(password_refusal(f"{user}@{address}" if user and address else
                                          address or "HOST"), password.name_location)
    for child in entity.children:
        raise ParseError(f"<machine> takes no <{child.tag}> (roslaunch refuses <env> in "
                         "<machine> since ROS Fuerte); put the <env> in the <node>, or "
                         "around it", child.location)
    _known(entity, set(MACHINE_ATTRS))
    for needed in ("name", "address"):
        if needed not in entity.attributes:
            raise ParseError(f"<machine> tag is missing required attribute: {needed}",
                             entity.location)
    _machine_values(entity)
    return _copy(entity, "roslaunch_machine", {name: name for name in MACHINE_ATTRS})


def _machine_values(entity: Entity) -> None:
    """default= (any case, as roslaunch lowers it), timeout= and ssh-port=, as written."""
    default = entity.attributes.get("default")
    word = _literal(entity, "default")
    if default is not None and word is not None:
        if word.strip().lower() not in DEFAULTS:
            raise ParseError(f"<machine default='{word}'>: expected true, false or never"
                             f"{did_you_mean(word.lower(), DEFAULTS)}", default.location)
        entity.attributes["default"] = Attribute(word.strip().lower(), default.location)
    timeout = _literal(entity, "timeout")
    if "timeout" in entity.attributes and timeout is not None and not _number(timeout, 0.0):
        raise ParseError(f"<machine timeout='{timeout}'>: expected a number of seconds > 0",
                         entity.attributes["timeout"].location)
    port = _literal(entity, "ssh-port")
    if "ssh-port" in entity.attributes and port is not None and \
            not (port.strip().isdigit() and 1 <= int(port) <= 65535):
        raise ParseError(f"<machine ssh-port='{port}'>: expected a port number, 1 to 65535",
                         entity.attributes["ssh-port"].location)


def _number(text: str, above: float) -> bool:
    """Whether `text` is a finite number > `above`."""
    try:
        value = float(text)
    except ValueError:
        return False
    return value > above and value != float("inf")


def _ns_given(entity: Entity) -> None:
    """xmlloader._ns_clear_params_attr: an ns= that is there is not empty."""
    ns = entity.attributes.get("ns")
    if ns is not None and not str(ns.value).strip():
        raise ParseError(f"<{entity.tag}> tag has an empty 'ns' attribute (leave it out for "
                         "the enclosing namespace)", ns.location)


_LEGAL_NAME = re.compile(r"[~/A-Za-z][\w/]*")


def _remap_names(entity: Entity) -> None:
    """roslaunch's loader.add_remap: from= and to= are given and are legal ROS names."""
    for key in ("from", "to"):
        attribute = entity.attributes.get(key)
        text = str(attribute.value).strip() if attribute is not None else ""
        if attribute is None or not text:
            raise ParseError(f"<remap> needs a non-empty {key}=", (attribute or entity).location)
        if "$(" not in text and (not _LEGAL_NAME.fullmatch(text) or "//" in text):
            raise ParseError(f"remap {key} [{text}] is not a valid ROS name (letters, digits, "
                             "'_' and '/', starting with a letter, '/' or '~')",
                             attribute.location)


def _bool_word(entity: Entity, name: str) -> bool:
    """A literal boolean attribute as roslaunch's _bool_attr reads it: true or false (any
    case), nothing else; one made by a substitution is read when it runs."""
    attribute = entity.attributes.get(name)
    if attribute is None or "$(" in str(attribute.value):
        return False
    word = str(attribute.value).lower()
    if word not in ("true", "false"):
        raise ParseError(f"{name}='{attribute.value}': roslaunch's {name} is true or false",
                         attribute.location)
    return word == "true"


def _warning(text: str, where: Location) -> Entity:
    """What roslaunch only warns about (and then goes on): said when the launch runs."""
    made = Entity("log", where, nested_in_children=True)
    made.attributes.update(message=_text(text, where), level=_text("warn", where))
    return made


def _test(entity: Entity) -> Entity:
    """`<test>`: its node, under a `rostest` that names it and gives its limits."""
    test = _copy(entity, "rostest", {"test-name": "test-name", "time-limit": "time-limit",
                                     "retry": "retry"})
    node = _node(entity)
    node.attributes.pop("on_exit", None)  # (rostest, not the node's exit, ends the launch)
    test.children.append(node)
    return test


NODE_ATTRS = {"pkg": "pkg", "type": "exec", "name": "name", "ns": "namespace", "args": "args",
              "output": "output", "respawn": "respawn", "respawn_delay": "respawn_delay",
              "launch-prefix": "launch-prefix", "cwd": "cwd"}


def _node(entity: Entity) -> Entity:
    test = entity.tag == "test"
    _known(entity, {*NODE_ATTRS, "required", "clear_params", "machine",
                    *(("time-limit", "retry", "test-name") if test else ())})
    for needed in ("pkg", "type", "test-name" if test else "name"):
        if needed not in entity.attributes:
            raise ParseError(f"roslaunch's <{entity.tag}> needs '{needed}'", entity.location)
    for refused in ("respawn", "respawn_delay", "output") if test else ():
        if refused in entity.attributes:  # (xmlloader._test_attrs)
            raise ParseError(f"<test> tags cannot have '{refused}' attribute (rostest runs a "
                             "test once, and shows its output)",
                             entity.attributes[refused].name_location)
    _ns_given(entity)
    flags = {name: _bool_word(entity, name) for name in ("respawn", "required")}
    if flags["respawn"] and flags["required"]:
        raise ParseError("respawn and required cannot both be set to true (a required node "
                         "ends the launch when it exits)", entity.attributes["required"].location)
    node = _copy(entity, "node", NODE_ATTRS)
    node.attributes["unique"] = _text("true", entity.location)
    node.attributes["server"] = _text("true", entity.location)
    node.attributes["ros1"] = _text("true", entity.location)  # roslaunch's command line
    if "name" not in entity.attributes and entity.tag == "test":
        node.attributes["name"] = entity.attributes.get("test-name") or \
            entity.attributes["type"]
    cwd = entity.attributes.get("cwd")
    if cwd is not None:  # ROS 1's cwd is a word: ROS_HOME (the default) or node
        del node.attributes["cwd"]
        word = str(cwd.value).strip()
        if "$(" not in word and word.lower() not in ("ros_home", "node"):
            raise ParseError(f"cwd='{word}': roslaunch's cwd is ROS_HOME or node",
                             cwd.location)
        node.attributes["home"] = Attribute("node" if word == "node" else "ROS_HOME",
                                            cwd.location)
    required = entity.attributes.get("required")
    if entity.tag == "test" or (required is not None and
                                str(required.value).strip().lower() == "true"):
        node.attributes["on_exit"] = _text("shutdown", entity.location)
    if "machine" in entity.attributes:  # checked against the launch's <machine>s
        node.attributes["machine"] = entity.attributes["machine"]
    for child in entity.children:
        for condition, field in (("if", "only_if"), ("unless", "only_unless")):
            if condition in child.attributes:  # roslaunch takes them on a node's children too
                child.attributes[field] = child.attributes.pop(condition)
        if child.tag == "param":
            node.children.append(_param_entry(child))
        elif child.tag == "rosparam":
            node.children += _rosparam_entries(child)
        elif child.tag == "remap":
            _known(child, {"from", "to"})
            _remap_names(child)
            node.children.append(_copy(child, "remap", {"from": "from", "to": "to"}))
        elif child.tag == "env":
            _known(child, {"name", "value"})
            node.children.append(_copy(child, "env", {"name": "name", "value": "value"}))
        else:
            raise ParseError(f"roslaunch's <node> takes <param>, <rosparam>, <remap> and "
                             f"<env>, not <{child.tag}>", child.location)
    return node




def _param_attrs(entity: Entity, made: Entity) -> None:
    _known(entity, {"name", "value", "type", "textfile", "binfile", "command"})
    if "binfile" in entity.attributes:
        raise ParseError("<param binfile=> is not supported: launcher's parameters hold text, "
                         "numbers, bools and lists, not a file's bytes; use textfile= for "
                         "text", entity.location)
    for key in ("value", "command", "textfile"):
        if key in entity.attributes:
            made.attributes[key] = entity.attributes[key]
    if "value" in entity.attributes:  # roslaunch strips value= (not a file's or command's text)
        value = entity.attributes["value"]
        made.attributes["value"] = Attribute(str(value.value).strip(), value.location)
    given = [k for k in ("value", "command", "textfile") if k in entity.attributes]
    if len(given) != 1:
        raise ParseError("<param> needs exactly one of value=, command= and textfile=",
                         entity.location)
    # roslaunch's types, as its loader converts (ros1:auto: an untyped value, a file's text
    # and a command's output too, as loader.param_value has it)
    kind = entity.attributes.get("type")
    if kind is not None:
        word = str(kind.value).lower().strip()
        if "$(" not in word and word not in ROS1_TYPES:
            raise ParseError(f"<param type='{word}'>: roslaunch's types are "
                             f"{', '.join(ROS1_TYPES)}{did_you_mean(word, ROS1_TYPES)}",
                             kind.location)
        made.attributes["type"] = Attribute(f"ros1:{word}", kind.location)
    else:
        made.attributes["type"] = _text("ros1:auto", entity.location)


def _param_entry(entity: Entity) -> Entity:
    """A node's `<param>`: its private parameter."""
    made = Entity("param", entity.location, nested_in_children=True)
    made.attributes["name"] = _private(entity)
    _param_attrs(entity, made)
    _carry_conditions(entity, made)
    return made


def _carry_conditions(entity: Entity, made: Entity) -> None:
    for condition in ENTRY_CONDITIONS:
        if condition in entity.attributes:
            made.attributes[condition] = entity.attributes[condition]


def _private(entity: Entity) -> Attribute:
    name = entity.attributes.get("name")
    if name is None:
        raise ParseError("<param> needs name=", entity.location)
    text = str(name.value)
    return Attribute(text[1:] if text.startswith("~") else text, name.location)


def _global_param(entity: Entity) -> Entity:
    """A `<param>` outside a node: on the graph's parameter server, and a parameter of every
    node after it in its scope (a `~name`: of those nodes alone)."""
    made = _copy(entity, "set_parameter", {})
    name = entity.attributes.get("name")
    if name is None:
        raise ParseError("<param> needs name=", entity.location)
    # a ~name is each later node's own (xmlloader._param_tag: context.add_param), on the
    # server under that node's name alone
    if str(name.value).strip().startswith("~"):
        made.attributes["private"] = _text("true", entity.location)
    else:
        made.attributes["server"] = _text("true", entity.location)
    made.attributes["name"] = Attribute(str(name.value).strip().lstrip("~"), name.location)
    _param_attrs(entity, made)
    return made


ROSPARAM_ATTRS = {"command", "file", "param", "ns", "subst_value", "#text"}


def _loads(entity: Entity) -> bool:
    """Whether a `<rosparam>` loads (else it dumps or deletes); its attributes checked."""
    _known(entity, ROSPARAM_ATTRS)
    command = str(entity.attributes["command"].value) if "command" in entity.attributes \
        else "load"
    if command in ("dump", "delete"):
        return False
    if command != "load":
        raise ParseError(f"<rosparam command='{command}'>: expected load, dump or delete",
                         entity.attributes["command"].location)
    return True


def _empty(entity: Entity) -> bool:
    """A `<rosparam>` with no file and no YAML: it loads nothing (roslaunch: an empty map)."""
    return "file" not in entity.attributes and "#text" not in entity.attributes


def _rosparam_into(entity: Entity, made: Entity) -> Entity:
    """A `<rosparam>`'s attributes as the param entry (or set_parameter) takes them; `ns` and
    `param` together name `ns/param`, as roslaunch has it."""
    for key, new in (("file", "rosparam_file"), ("#text", "rosparam"),
                     ("subst_value", "allow_substs")):
        if key in entity.attributes:
            made.attributes[new] = entity.attributes[key]
    given = entity.attributes.get("subst_value")
    if "#text" in entity.attributes and (given is None or "$(" not in str(given.value) and
                                         str(given.value).strip().lower() not in ("true", "1")):
        # roslaunch reads a rosparam's YAML as written unless subst_value is true
        text = entity.attributes["#text"]
        made.attributes["rosparam"] = Attribute(text.value, text.location, text.text_offset,
                                                text.key_location, text.string, text.roslaunch,
                                                literal=True)
    ns, param = entity.attributes.get("ns"), entity.attributes.get("param")
    if ns is not None and param is not None:
        made.attributes["name"] = Attribute(f"{ns.value}/{param.value}", ns.location)
    elif ns is not None or param is not None:
        made.attributes["name"] = ns or param  # type: ignore[assignment]
    return made


def _rosparam_entries(entity: Entity) -> list[Entity]:
    """A node's `<rosparam>`: parameters from ROS 1 YAML (a plain map)."""
    if not _loads(entity) or _empty(entity):
        return []  # a node's own dump or delete: nothing to act on
    made = _rosparam_into(entity, Entity("param", entity.location, nested_in_children=True))
    _carry_conditions(entity, made)
    return [made]


def _global_rosparam(entity: Entity) -> list[Entity]:
    made = _copy(entity, "set_parameter", {})
    made.attributes["server"] = _text("true", entity.location)
    if _loads(entity) and _empty(entity):
        return []
    if not _loads(entity):
        # (roslaunch runs `rosparam delete|dump` before it uploads the launch's parameters)
        made.attributes["rosparam_command"] = entity.attributes["command"]
    made = _rosparam_into(entity, made)
    name = made.attributes.get("name")
    if name is not None and str(name.value).startswith("~"):
        # a private name outside a node is the launcher's own: roslaunch sets it on the
        # server as itself (/roslaunch), and no node gets it
        made.attributes["name"] = Attribute("/roslaunch/" + str(name.value)[1:].strip("/"),
                                            name.location)
        made.attributes["server_only"] = _text("true", entity.location)
    return [made]


def _clearing(entity: Entity, name: str) -> list[Entity]:
    """roslaunch's clear_params="true": the parameter server forgets what it holds under the
    group's namespace, or the node's private one, before the launch sets its own (only on the
    server: what this launch sets stays)."""
    flag = entity.attributes.get("clear_params")
    if flag is None or str(flag.value).strip().lower() not in ("true", "1"):
        return []
    if entity.tag in ("group", "include") and "ns" not in entity.attributes:
        raise ParseError(f"<{entity.tag} clear_params=\"true\">: 'ns' attribute must be set in "
                         "order to use 'clear_params' (roslaunch never clears the root "
                         "namespace)", flag.location)
    if entity.tag == "node" and not name:
        raise ParseError("<node clear_params=\"true\"> needs name=: it clears the node's "
                         "private parameters", flag.location)
    made = Entity("set_parameter", entity.location, nested_in_children=True)
    made.attributes.update(name=_text(name, flag.location),
                           rosparam_command=_text("delete", flag.location),
                           server=_text("true", flag.location))
    return [made]


def _include(entity: Entity) -> Entity:
    _known(entity, {"file", "ns", "clear_params", "pass_all_args"})
    _ns_given(entity)
    include = _copy(entity, "include", {"file": "file"})
    include.attributes["scoped"] = _text("true", entity.location)
    include.attributes["pass_all_args"] = entity.attributes.get("pass_all_args") or \
        _text("false", entity.location)  # roslaunch: the file gets only what is passed
    envs = []  # roslaunch's <env> in an <include>: for the included file's nodes
    for child in entity.children:
        if child.tag == "env":
            _known(child, {"name", "value"})
            envs.append(_copy(child, "set_env", {"name": "name", "value": "value"}))
            continue
        if child.tag != "arg":
            raise ParseError(f"roslaunch's <include> takes <arg> and <env> children, not "
                             f"<{child.tag}>", child.location)
        _known(child, {"name", "value", "default", "doc"})
        arg = _copy(child, "arg", {"name": "name", "value": "value"})
        if "value" not in child.attributes and "default" in child.attributes:
            arg.attributes["value"] = child.attributes["default"]
        include.children.append(arg)
    if "ns" not in entity.attributes and not envs:
        _clearing(entity, "")  # (refused without ns)
        return include
    group = _copy(entity, "group", {})  # (the namespace and the variables end with it)
    include.attributes.pop("if", None)
    include.attributes.pop("unless", None)
    if "ns" in entity.attributes:
        push = Entity("push_ros_namespace", entity.location, nested_in_children=True)
        push.attributes["namespace"] = entity.attributes["ns"]
        group.children.append(push)
    group.children += [*envs, *_clearing(entity, ""), include]
    return group

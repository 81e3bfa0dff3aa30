"""ROS 2 cases: launch_ros's XML and YAML frontends, per tag × attribute × substitution ×
nesting. Most shapes are written in both frontends, since each has its own parser."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any


def node(name: str = "n", attrs: str = "", body: str = "") -> str:
    head = f'<node pkg="probe" exec="probe" name="{name}"{attrs}'
    return f"{head}>{body}</node>" if body else f"{head}/>"


def xml(name: str, body: str, **extra: Any) -> dict[str, Any]:
    files = {"main.launch.xml": f"<launch>\n{body}\n</launch>\n", **extra.pop("files", {})}
    return {"name": f"ros2/xml/{name}", "files": files, "main": "main.launch.xml", **extra}


def yaml(name: str, body: str, **extra: Any) -> dict[str, Any]:
    files = {"main.launch.yaml": f"launch:\n{body}", **extra.pop("files", {})}
    return {"name": f"ros2/yaml/{name}", "files": files, "main": "main.launch.yaml", **extra}


XML_PARAM_VALUES = {
    "int": "1", "negative": "-3", "float": "1.5", "exponent": "1e3", "true": "true",
    "True": "True", "word": "hello", "spaced": " a b ", "empty": "", "int-list": "[1, 2]",
    "str-list": "['a', 'b']", "mixed-list": "[1, 'a']", "float-list": "[1.0, 2.5]",
    "bool-list": "[true, false]", "dict": "{a: 1}", "quoted-number": "'1'",
    "leading-zero": "007", "hex": "0x10", "yes": "yes", "url": "http://x/y", "colon": "a: b",
}


def xml_parameters() -> Iterator[dict[str, Any]]:
    for label, value in XML_PARAM_VALUES.items():
        yield xml(f"param/value-{label}", node(body=f'<param name="p" value="{value}"/>'))
    yield xml("param/value-sep", node(body='<param name="p" value="a,b,c" value-sep=","/>'))
    yield xml("param/value-sep-numbers", node(body='<param name="p" value="1;2" value-sep=";"/>'))
    yield xml("param/nested", node(body='<param name="group"><param name="x" value="1"/>'
                                        '<param name="y" value="b"/></param>'))
    yield xml("param/dotted", node(body='<param name="a.b.c" value="1"/>'))
    yield xml("param/from-file", node(body='<param from="$(dirname)/params.yaml"/>'),
              files={"params.yaml": "/**:\n  ros__parameters:\n    f: 1\n    g: [a, b]\n"})
    yield xml("param/from-file-by-name", node(body='<param from="$(dirname)/params.yaml"/>'),
              files={"params.yaml": "n:\n  ros__parameters:\n    f: 1\nother:\n"
                                    "  ros__parameters:\n    f: 2\n"})
    yield xml("param/from-package", node(body='<param from="$(find-pkg-share probe)'
                                              '/config/params.yaml"/>'))
    yield xml("param/from-missing-file", node(body='<param from="$(dirname)/nothing.yaml"/>'))
    yield xml("param/two-then-file", node(body='<param name="a" value="1"/><param from='
                                               '"$(dirname)/p.yaml"/><param name="b" value="2"/>'),
              files={"p.yaml": "/**:\n  ros__parameters:\n    a: 9\n"})
    yield xml("param/robot-description", node(body='<param name="robot_description" '
                                                   'value="&lt;robot name=&quot;r&quot;/&gt;"/>'))
    yield xml("param/substitution", '<arg name="v" default="3"/>' +
              node(body='<param name="p" value="$(var v)"/>'))
    yield xml("param/substitution-list", '<arg name="v" default="3"/>' +
              node(body='<param name="p" value="[$(var v), 4]"/>'))
    yield xml("param/no-value", node(body='<param name="p"/>'))
    yield xml("param/set-parameter", '<set_parameter name="s" value="1"/>' + node())
    yield xml("param/set-parameter-scoped", '<group><set_parameter name="s" value="1"/></group>'
              + node())
    yield xml("param/set-parameter-then-own", '<set_parameter name="p" value="global"/>' +
              node(body='<param name="p" value="own"/>'))
    yield xml("param/set-parameters-from-file",
              '<set_parameters_from_file filename="$(dirname)/p.yaml"/>' + node(),
              files={"p.yaml": "/**:\n  ros__parameters:\n    a: 9\n"})
    yield xml("param/set-use-sim-time", '<set_use_sim_time value="true"/>' + node())


YAML_PARAM_VALUES = {
    "int": "1", "float": "1.5", "bool": "true", "string": "hello", "quoted-int": "'1'",
    "int-list": "[1, 2]", "str-list": "[a, b]", "float-list": "[1.0, 2.5]",
    "bool-list": "[true, false]", "null": "null", "empty-string": "''", "mixed-list": "[1, a]",
    "nested": "{a: 1}", "exponent": "1e3", "yes": "yes", "big": "12345678901234",
}


def yaml_parameters() -> Iterator[dict[str, Any]]:
    for label, value in YAML_PARAM_VALUES.items():
        yield yaml(f"param/value-{label}", "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
                   f"    param:\n    - name: p\n      value: {value}\n")
    yield yaml("param/from-file", "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
               "    param:\n    - from: $(dirname)/params.yaml\n",
               files={"params.yaml": "/**:\n  ros__parameters:\n    f: 1\n"})
    yield yaml("param/nested-list", "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
               "    param:\n    - name: group\n      param:\n      - name: x\n        value: 1\n")
    yield yaml("param/substitution", "- arg:\n    name: v\n    default: '3'\n"
               "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
               "    param:\n    - name: p\n      value: $(var v)\n")


def node_attributes() -> Iterator[dict[str, Any]]:
    attrs = {
        "args": ' args="a b  c"',
        "args-quoted": ' args="a \'b c\'"',
        "namespace-relative": ' namespace="g"',
        "namespace-absolute": ' namespace="/g"',
        "namespace-nested": ' namespace="a/b"',
        "namespace-trailing": ' namespace="g/"',
        "exec-name": ' exec_name="label"',
        "ros-args": ' ros_args="--log-level warn"',
        "output-screen": ' output="screen"',
        "launch-prefix": ' launch-prefix="env PROBE_PREFIXED=1"',
        "cwd": ' cwd="/"',
        "if-false": ' if="false"',
        "unless-false": ' unless="false"',
        "if-bad": ' if="maybe"',
        "if-and-unless": ' if="true" unless="false"',
        "unknown-attribute": ' colour="red"',
        "respawn-false": ' respawn="false"',
        "sigterm-timeout": ' sigterm_timeout="1"',
    }
    for label, text in attrs.items():
        yield xml(f"node/{label}", node(attrs=text))
    yield xml("node/no-name", '<node pkg="probe" exec="probe"/>')
    yield xml("node/no-pkg", '<node exec="probe" name="n"/>')
    yield xml("node/missing-package", '<node pkg="no_such_pkg" exec="probe" name="n"/>')
    yield xml("node/missing-exec", '<node pkg="probe" exec="nothing" name="n"/>')
    yield xml("node/name-with-slash", '<node pkg="probe" exec="probe" name="a/b"/>')
    yield xml("node/two-same-name", node() + node())
    yield xml("node/respawn", node(attrs=' respawn="true" respawn_delay="0.5"'), stop_after=3.0)
    yield xml("node/env", node(body='<env name="PROBE_E" value="1"/>'))
    yield xml("node/env-twice", node(body='<env name="PROBE_E" value="1"/>'
                                          '<env name="PROBE_E" value="2"/>'))
    yield xml("node/anon-name", '<node pkg="probe" exec="probe" name="$(anon n)"/>')
    yield xml("node/executable", '<executable cmd="$(find-pkg-prefix probe)/lib/probe/probe a b"'
              ' name="e"/>')
    yield xml("node/executable-env", '<executable cmd="$(find-pkg-prefix probe)/lib/probe/probe"'
              ' name="e"><env name="PROBE_E" value="1"/></executable>')
    for label, text in (("args", "    args: a b\n"), ("namespace", "    namespace: g\n"),
                        ("if-false", "    if: 'false'\n"), ("exec-name", "    exec_name: x\n"),
                        ("ros-args", "    ros_args: --log-level warn\n"),
                        ("unknown-key", "    colour: red\n"),
                        ("respawn-bool", "    respawn: true\n    respawn_delay: 0.5\n")):
        stop = 3.0 if "respawn" in label else None
        yield yaml(f"node/{label}", "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
                   + text, stop_after=stop)
    yield yaml("node/env", "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
               "    env:\n    - name: PROBE_E\n      value: '1'\n")


def remaps() -> Iterator[dict[str, Any]]:
    bodies = {
        "node": node(body='<remap from="a" to="b"/>'),
        "set-remap": '<set_remap from="a" to="b"/>' + node(),
        "set-remap-and-node": '<set_remap from="a" to="scope"/>' +
                              node(body='<remap from="a" to="own"/>'),
        "set-remap-after": node() + '<set_remap from="a" to="b"/>',
        "set-remap-in-group": '<group><set_remap from="a" to="b"/>' + node() + "</group>" +
                              node("m"),
        "set-remap-nested": '<set_remap from="x" to="outer"/><group><set_remap from="y" '
                            'to="inner"/>' + node(body='<remap from="z" to="own"/>') + "</group>",
        "set-remap-forwarding": '<group forwarding="false"><set_remap from="a" to="b"/>' +
                                node() + "</group>",
        "twice": node(body='<remap from="a" to="b"/><remap from="a" to="c"/>'),
        "private": node(body='<remap from="~/a" to="b"/>'),
        "with-var": '<let name="t" value="tt"/>' + node(body='<remap from="a" to="$(var t)"/>'),
        "node-rule": node(body='<remap from="n:a" to="b"/>'),
    }
    for label, body in bodies.items():
        yield xml(f"remap/{label}", body)
    yield yaml("remap/set-remap-and-node",
               "- set_remap:\n    from: a\n    to: scope\n"
               "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
               "    remap:\n    - from: a\n      to: own\n")


def namespaces() -> Iterator[dict[str, Any]]:
    bodies = {
        "push": '<group><push_ros_namespace namespace="g"/>' + node() + "</group>",
        "push-dash": '<group><push-ros-namespace namespace="g"/>' + node() + "</group>",
        "push-nested": '<group><push_ros_namespace namespace="a"/><group>'
                       '<push_ros_namespace namespace="b"/>' + node() + "</group></group>",
        "push-and-node-ns": '<group><push_ros_namespace namespace="a"/>' +
                            node(attrs=' namespace="b"') + "</group>",
        "push-and-node-absolute": '<group><push_ros_namespace namespace="a"/>' +
                                  node(attrs=' namespace="/b"') + "</group>",
        "push-absolute": '<group><push_ros_namespace namespace="/a"/><group>'
                         '<push_ros_namespace namespace="/b"/>' + node() + "</group></group>",
        "push-unscoped": '<push_ros_namespace namespace="g"/>' + node(),
        "push-leaks-not": '<group><push_ros_namespace namespace="g"/></group>' + node(),
        "group-scoped-false": '<group scoped="false"><push_ros_namespace namespace="g"/></group>'
                              + node(),
        "group-namespace-attr": '<group namespace="g">' + node() + "</group>",
    }
    for label, body in bodies.items():
        yield xml(f"namespace/{label}", body)
    yield yaml("namespace/push", "- group:\n    - push_ros_namespace:\n        namespace: g\n"
               "    - node:\n        pkg: probe\n        exec: probe\n        name: n\n")


def environment() -> Iterator[dict[str, Any]]:
    bodies = {
        "set-env": '<set_env name="PROBE_E" value="1"/>' + node(),
        "set-env-scoped": '<group><set_env name="PROBE_E" value="1"/></group>' + node(),
        "set-env-unscoped": '<group scoped="false"><set_env name="PROBE_E" value="1"/></group>'
                            + node(),
        "unset-env": '<unset_env name="PROBE_V"/>' + node(),
        "append-env": '<append_env name="PROBE_V" value="more"/>' + node(),
        "append-env-prepend": '<append_env name="PROBE_V" value="more" prepend="true"/>' + node(),
        "append-env-separator": '<append_env name="PROBE_V" value="more" separator=";"/>'
                                + node(),
        "append-env-unset": '<append_env name="PROBE_NEW" value="more"/>' + node(),
        "node-over-set-env": '<set_env name="PROBE_E" value="scope"/>' +
                             node(body='<env name="PROBE_E" value="own"/>'),
        "set-env-if-false": '<set_env name="PROBE_E" value="1" if="false"/>' + node(),
        "env-substitution": node(attrs=' args="$(env PROBE_V)"'),
        "env-default": node(attrs=' args="$(env PROBE_NOT_SET dflt)"'),
        "env-missing": node(attrs=' args="$(env PROBE_NOT_SET)"'),
        "optenv": node(attrs=' args="$(optenv PROBE_NOT_SET a b)"'),
        "reset-env": '<set_env name="PROBE_E" value="1"/><reset_env/>' + node(),
    }
    for label, body in bodies.items():
        yield xml(f"env/{label}", body, env={"PROBE_V": "shell"})


INCLUDED_XML = """<launch>
  <arg name="a" default="inner"/>
  <let name="leaked" value="yes"/>
  <node pkg="probe" exec="probe" name="inc" args="$(var a) $(dirname)"/>
</launch>
"""


def arguments() -> Iterator[dict[str, Any]]:
    bodies = {
        "default": '<arg name="a" default="x"/>' + node(attrs=' args="$(var a)"'),
        "missing": '<arg name="a"/>' + node(attrs=' args="$(var a)"'),
        "undeclared": node(attrs=' args="$(var nope)"'),
        "choice": '<arg name="a" default="x"><choice value="x"/><choice value="y"/></arg>' +
                  node(attrs=' args="$(var a)"'),
        "choice-bad-default": '<arg name="a" default="z"><choice value="x"/></arg>' +
                              node(attrs=' args="$(var a)"'),
        "let": '<let name="a" value="lv"/>' + node(attrs=' args="$(var a)"'),
        "let-overrides-arg": '<arg name="a" default="x"/><let name="a" value="lv"/>' +
                             node(attrs=' args="$(var a)"'),
        "let-in-group": '<group><let name="a" value="in"/></group><let name="b" value="o"/>' +
                        node(attrs=' args="$(var b)"'),
        "let-scoped-leak": '<group><let name="a" value="in"/></group>' +
                           node(attrs=' args="$(var a)"'),
        "let-unscoped": '<group scoped="false"><let name="a" value="in"/></group>' +
                        node(attrs=' args="$(var a)"'),
        "declared-twice": '<arg name="a" default="1"/><arg name="a" default="2"/>' +
                          node(attrs=' args="$(var a)"'),
        "description": '<arg name="a" default="1" description="the a"/>' +
                       node(attrs=' args="$(var a)"'),
        "var-default": node(attrs=' args="$(var nope dflt)"'),
        "include": '<include file="$(dirname)/inc.launch.xml"/>',
        "include-arg": '<include file="$(dirname)/inc.launch.xml"><arg name="a" value="given"/>'
                       "</include>",
        "include-leaks": '<include file="$(dirname)/inc.launch.xml"/>' +
                         node(attrs=' args="$(var leaked) $(var a)"'),
        "include-in-group": '<group><include file="$(dirname)/inc.launch.xml"/></group>' +
                            node(attrs=' args="$(var a outside)"'),
        "include-arg-from-command-line": '<include file="$(dirname)/inc.launch.xml"/>',
        "include-package": '<include file="$(find-pkg-share probe)/launch/probe.launch.xml">'
                           '<arg name="who" value="me"/></include>',
        "include-missing": '<include file="$(dirname)/nothing.launch.xml"/>',
        "include-if-false": '<include file="$(dirname)/inc.launch.xml" if="false"/>',
        "include-namespace": '<group><push_ros_namespace namespace="r"/>'
                             '<include file="$(dirname)/inc.launch.xml"/></group>',
    }
    for label, body in bodies.items():
        args = ("a:=cli",) if label in ("include-arg-from-command-line",) else ()
        yield xml(f"arg/{label}", body, files={"inc.launch.xml": INCLUDED_XML}, args=args)
    yield xml("arg/given", '<arg name="a" default="x"/>' + node(attrs=' args="$(var a)"'),
              args=("a:=given",))
    yield xml("arg/choice-bad-given", '<arg name="a" default="x"><choice value="x"/></arg>' +
              node(attrs=' args="$(var a)"'), args=("a:=z",))
    yield xml("arg/given-undeclared", node(), args=("zzz:=1",))
    yield yaml("arg/default", "- arg:\n    name: a\n    default: x\n"
               "- node:\n    pkg: probe\n    exec: probe\n    name: n\n    args: $(var a)\n")
    yield yaml("arg/missing", "- arg:\n    name: a\n"
               "- node:\n    pkg: probe\n    exec: probe\n    name: n\n    args: $(var a)\n")
    yield yaml("arg/include-arg", "- include:\n    file: $(dirname)/inc.launch.xml\n"
               "    arg:\n    - name: a\n      value: y\n",
               files={"inc.launch.xml": INCLUDED_XML})


SUBSTITUTIONS = {
    "eval": "$(eval '1 + 2')",
    "eval-math": "$(eval 'math.pi > 3')",
    "eval-var": "$(eval '\"$(var a)\" * 2')",
    "dirname": "$(dirname)",
    "filename": "$(filename)",
    "find-pkg-share": "$(find-pkg-share probe)",
    "find-pkg-prefix": "$(find-pkg-prefix probe)",
    "find-pkg-missing": "$(find-pkg-share no_such_pkg)",
    "find-exec": "$(find-exec sh)",
    "exec-in-pkg": "$(exec-in-pkg probe probe)",
    "command": "$(command 'echo hi there')",
    "command-fails": "$(command 'false')",
    "not": "$(not true)",
    "and": "$(and true false)",
    "or": "$(or false true)",
    "equals": "$(equals 1 1.0)",
    "equals-strings": "$(equals a a)",
    "not-equals": "$(not-equals a b)",
    "if": "$(if true yes no)",
    "if-false": "$(if false yes no)",
    "anon-same": "$(anon a)=$(anon a)",
    "var": "$(var a)",
    "var-glued": "x$(var a)y",
    "unknown": "$(nope)",
    "unclosed": "$(var a",
    "quoted": "'a b' c",
    "dollar": "cost$5",
    "arg-alias": "$(arg a)",
    "find-alias": "$(find probe)",
    "optenv-alias": "$(optenv PROBE_V d)",
}


def substitutions() -> Iterator[dict[str, Any]]:
    for label, text in SUBSTITUTIONS.items():
        attr = text.replace('"', "&quot;")
        yield xml(f"subst/{label}", '<arg name="a" default="va"/>' +
                  node(attrs=f' args="{attr}"'), env={"PROBE_V": "shell"})
    for label in ("eval", "dirname", "not", "equals", "if", "command"):
        yaml_text = SUBSTITUTIONS[label].replace("'", "''")
        yield yaml(f"subst/{label}", "- arg:\n    name: a\n    default: va\n"
                   "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
                   f"    args: '{yaml_text}'\n")


def conditions() -> Iterator[dict[str, Any]]:
    for value in ("true", "false", "True", "FALSE", "1", "0", "yes", ""):
        yield xml(f"condition/if-{value or 'empty'}", node(attrs=f' if="{value}"'))
    yield xml("condition/var", '<arg name="on" default="false"/>' +
              node(attrs=' if="$(var on)"'), args=("on:=true",))
    yield xml("condition/group-if", '<group if="false">' + node() + "</group>" + node("m"))
    yield xml("condition/let-if", '<let name="a" value="x" if="false"/>' +
              node(attrs=' args="$(var a dflt)"'))
    yield xml("condition/timer", '<timer period="0.2">' + node() + "</timer>")
    yield xml("condition/timer-if", '<timer period="0.2" if="false">' + node() + "</timer>"
              + node("m"))
    yield yaml("condition/if-false", "- node:\n    pkg: probe\n    exec: probe\n    name: n\n"
               "    if: 'false'\n- node:\n    pkg: probe\n    exec: probe\n    name: m\n")


CONTAINER = '<node_container pkg="probe" exec="probe" name="c" namespace="/">{}</node_container>'


def composition() -> Iterator[dict[str, Any]]:
    yield xml("composition/empty-container", CONTAINER.format(""))
    yield xml("composition/switched-off", CONTAINER.format(
        '<composable_node pkg="p" plugin="p::N" name="a" if="false"/>'))
    yield xml("composition/unless-true", CONTAINER.format(
        '<composable_node pkg="p" plugin="p::N" name="a" unless="true"/>'))
    yield xml("composition/container-if-false", CONTAINER.replace(
        'name="c"', 'name="c" if="false"').format("") + node())
    yield yaml("composition/switched-off",
               "- node_container:\n    pkg: probe\n    exec: probe\n    name: c\n"
               "    namespace: /\n    composable_node:\n    - pkg: p\n      plugin: p::N\n"
               "      name: a\n      if: 'false'\n")


def errors() -> Iterator[dict[str, Any]]:
    yield xml("error/not-xml", "<node")
    yield xml("error/unknown-tag", "<nodes/>")
    yield {"name": "ros2/xml/error/wrong-root", "files": {"main.launch.xml": "<robot/>"},
           "main": "main.launch.xml"}
    yield {"name": "ros2/yaml/error/not-a-map", "files": {"main.launch.yaml": "- a\n"},
           "main": "main.launch.yaml"}
    yield {"name": "ros2/yaml/error/no-launch-key", "files": {"main.launch.yaml": "nodes: []\n"},
           "main": "main.launch.yaml"}
    yield yaml("error/unknown-tag", "- nodes:\n    pkg: probe\n")
    yield yaml("error/bad-yaml", "- node: [\n")
    # (the shutdown first: the node after it is never started, so nothing races)
    yield xml("error/shutdown", '<shutdown reason="done"/>' + node())
    yield xml("error/log", '<log message="hello"/>' + node())


def specs() -> Iterator[dict[str, Any]]:
    for family in (xml_parameters, yaml_parameters, node_attributes, remaps, namespaces,
                   environment, arguments, substitutions, conditions, composition, errors):
        yield from family()

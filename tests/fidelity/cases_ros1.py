"""ROS 1 cases: roslaunch XML, per tag × attribute × substitution × nesting."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any


def node(name: str = "n", attrs: str = "", body: str = "") -> str:
    if body:
        return f'<node name="{name}" pkg="probe" type="probe.py"{attrs}>{body}</node>'
    return f'<node name="{name}" pkg="probe" type="probe.py"{attrs}/>'


NODE_A = node(attrs=' args="$(arg a)"')
NODE_B = node(attrs=' args="$(arg b)"')
NODE_MA = node("m", attrs=' args="$(arg a)"')
NODE_NS_H = node(attrs=' ns="h"')
NODE_NS_ABS_H = node(attrs=' ns="/h"')


def launch(name: str, body: str, **extra: Any) -> dict[str, Any]:
    files = {"main.launch": f"<launch>\n{body}\n</launch>\n", **extra.pop("files", {})}
    return {"name": f"ros1/{name}", "files": files, **extra}


PARAM_VALUES = {
    "int": "1", "negative": "-3", "hex": "0x1A", "float": "1.5", "exponent": "1e3",
    "underscore": "1_000", "true": "true", "True": "True", "TRUE": "TRUE", "false": "false",
    "yes": "yes", "word": "hello", "spaced": "  spaced out  ", "empty": "",
    "list": "[1, 2]", "dict": "{a: 1}", "zero-float": "0.0", "leading-zero": "007",
    "trailing-dot": "1.", "leading-dot": ".5", "plus": "+4", "big": "12345678901234",
    "colon": "a: b", "quote": "'q'",
}

TYPED_VALUES = [
    ("int", "3"), ("int", "3.7"), ("int", "x"), ("double", "3"), ("double", "x"),
    ("str", "3"), ("str", "true"), ("string", "3"), ("bool", "true"), ("bool", "True"),
    ("bool", "1"), ("bool", "no"), ("yaml", "[1, 2]"), ("yaml", "{a: {b: 1}}"),
    ("yaml", "hello"), ("yaml", "3"), ("auto", "3"), ("nope", "3"),
]


def parameters() -> Iterator[dict[str, Any]]:
    for label, value in PARAM_VALUES.items():
        yield launch(f"param/value-{label}", f'<param name="p" value="{value}"/>\n{node()}')
    for index, (kind, value) in enumerate(TYPED_VALUES):
        yield launch(f"param/typed-{kind}-{index}",
                     f'<param name="p" type="{kind}" value="{value}"/>\n{node()}')
    places = {
        "global": '<param name="/x" value="1"/>',
        "relative": '<param name="x" value="1"/>',
        "private-top": '<param name="~x" value="1"/>',
        "group-relative": '<group ns="g"><param name="x" value="1"/></group>',
        "group-global": '<group ns="g"><param name="/x" value="1"/></group>',
        "group-private": '<group ns="g"><param name="~x" value="1"/></group>',
        "nested": '<param name="a/b/c" value="1"/>',
        "trailing-slash": '<param name="a/" value="1"/>',
    }
    for label, text in places.items():
        yield launch(f"param/place-{label}", f"{text}\n{node()}\n"
                     f'<group ns="g">{node("m")}</group>')
    in_node = {
        "plain": '<param name="x" value="1"/>',
        "global": '<param name="/x" value="1"/>',
        "private": '<param name="~x" value="1"/>',
        "nested": '<param name="a/b" value="1"/>',
    }
    for label, text in in_node.items():
        yield launch(f"param/in-node-{label}", node(body=text))
        yield launch(f"param/in-node-ns-{label}", node(attrs=' ns="g"', body=text))
    yield launch("param/private-before-nodes",
                 f'<param name="~x" value="1"/>\n{node("a")}\n{node("b")}')
    yield launch("param/private-after-node",
                 f'{node("a")}\n<param name="~x" value="1"/>\n{node("b")}')
    yield launch("param/overridden", f'<param name="x" value="1"/>\n<param name="x" value="2"/>'
                 f'\n{node()}')
    yield launch("param/dict-then-scalar",
                 f'<param name="a/b" value="1"/>\n<param name="a" value="2"/>\n{node()}')
    sources = {
        "textfile": '<param name="p" textfile="$(dirname)/text.txt"/>',
        "command": '<param name="p" command="echo hello world"/>',
        "command-number": '<param name="p" command="echo 42"/>',
        "command-typed": '<param name="p" type="str" command="echo 42"/>',
        "textfile-typed": '<param name="p" type="yaml" textfile="$(dirname)/text.txt"/>',
        "textfile-missing": '<param name="p" textfile="$(dirname)/missing.txt"/>',
        "command-fails": '<param name="p" command="false"/>',
        "two-sources": '<param name="p" value="1" command="echo 2"/>',
        "no-value": '<param name="p"/>',
        "no-name": '<param value="1"/>',
    }
    for label, text in sources.items():
        yield launch(f"param/source-{label}", f"{text}\n{node()}",
                     files={"text.txt": "line one\n42\n"})
    for cond in ("if=\"true\"", "if=\"false\"", "unless=\"true\"", "unless=\"0\"",
                 'if="$(arg on)"', 'if="maybe"'):
        label = cond.replace('"', "").replace("=", "-").replace("$(arg on)", "arg")
        yield launch(f"param/condition-{label}", f'<arg name="on" default="1"/>\n'
                     f'<param name="p" value="1" {cond}/>\n{node()}')


ROSPARAM_YAML = """a: 1
b: 2.5
c: hello
d: [1, two, 3.0]
e: {f: {g: true}}
h: yes
i: 'quoted'
j: 1e3
k: !!str 5
l: null
"""


def rosparams() -> Iterator[dict[str, Any]]:
    files = {"params.yaml": ROSPARAM_YAML, "subst.yaml": "v: $(arg x)\nw: $(env PROBE_V)\n"}
    bodies = {
        "file": '<rosparam command="load" file="$(dirname)/params.yaml"/>',
        "file-find": '<rosparam command="load" file="$(find probe)/config/params.yaml"/>',
        "file-ns": '<rosparam command="load" file="$(dirname)/params.yaml" ns="sub"/>',
        "file-in-group": '<group ns="g"><rosparam file="$(dirname)/params.yaml"/></group>',
        "file-param": '<rosparam file="$(dirname)/params.yaml" param="under"/>',
        "inline": "<rosparam>\nx: 1\ny: [a, b]\n</rosparam>",
        "inline-param": '<rosparam param="x">[1, 2, 3]</rosparam>',
        "inline-scalar": '<rosparam param="x">5</rosparam>',
        "inline-ns": '<rosparam ns="sub">\nx: 1\n</rosparam>',
        "inline-global-ns": '<group ns="g"><rosparam ns="/top">\nx: 1\n</rosparam></group>',
        "inline-private": '<rosparam ns="~">\nx: 1\n</rosparam>',
        "subst-off": '<arg name="x" default="7"/><rosparam file="$(dirname)/subst.yaml"/>',
        "subst-on": '<arg name="x" default="7"/>'
                    '<rosparam file="$(dirname)/subst.yaml" subst_value="true"/>',
        "subst-inline": '<arg name="x" default="7"/>'
                        '<rosparam subst_value="true">\nv: $(arg x)\n</rosparam>',
        "delete": '<rosparam>\nx: 1\ny: 2\n</rosparam>\n<rosparam command="delete" param="x"/>',
        "delete-missing": '<rosparam command="delete" param="nothing"/>',
        "empty": "<rosparam></rosparam>",
        "bad-yaml": "<rosparam>\nx: [1, 2\n</rosparam>",
        "missing-file": '<rosparam file="$(dirname)/missing.yaml"/>',
        "bad-command": '<rosparam command="explode">\nx: 1\n</rosparam>',
        "if-false": '<rosparam if="false">\nx: 1\n</rosparam>',
        "unless-false": '<rosparam unless="false">\nx: 1\n</rosparam>',
        "then-param": '<rosparam>\nx: {a: 1}\n</rosparam>\n<param name="x/b" value="2"/>',
        "param-then": '<param name="x/b" value="2"/>\n<rosparam>\nx: {a: 1}\n</rosparam>',
        "in-node": None,
    }
    for label, body in bodies.items():
        if body is None:
            body = node(body='<rosparam>\nx: 1\n</rosparam><rosparam ns="s">\ny: 2\n</rosparam>')
            yield launch(f"rosparam/{label}", body, files=files, env={"PROBE_V": "env value"})
            continue
        yield launch(f"rosparam/{label}", f"{body}\n{node()}", files=files,
                     env={"PROBE_V": "env value"})


def arguments() -> Iterator[dict[str, Any]]:
    yield launch("arg/default", f'<arg name="a" default="x"/>\n{NODE_A}')
    yield launch("arg/default-overridden", f'<arg name="a" default="x"/>\n'
                 f'{NODE_A}', args=("a:=y",))
    yield launch("arg/value", f'<arg name="a" value="x"/>\n{NODE_A}')
    yield launch("arg/value-overridden", f'<arg name="a" value="x"/>\n'
                 f'{NODE_A}', args=("a:=y",))
    yield launch("arg/required-given", f'<arg name="a"/>\n{NODE_A}',
                 args=("a:=given",))
    yield launch("arg/required-missing", f'<arg name="a"/>\n{NODE_A}')
    yield launch("arg/undeclared", node(attrs=' args="$(arg nope)"'))
    yield launch("arg/declared-twice", f'<arg name="a" default="1"/>\n<arg name="a" default="2"/>'
                 f"\n{node()}")
    yield launch("arg/unused-on-command-line", node(), args=("zzz:=1",))
    yield launch("arg/default-and-value", f'<arg name="a" default="1" value="2"/>\n{node()}')
    yield launch("arg/doc", f'<arg name="a" default="1" doc="the a"/>\n{node()}')
    yield launch("arg/from-arg", '<arg name="a" default="1"/>\n<arg name="b" default="$(arg a)2"/>'
                 f'\n{NODE_B}', args=("a:=9",))
    yield launch("arg/in-group", '<group ns="g"><arg name="a" default="in"/>'
                 f'{NODE_A}</group>\n<arg name="a" default="out"/>\n'
                 f'{NODE_MA}')
    yield launch("arg/in-group-not-outside", '<group><arg name="a" default="in"/></group>\n'
                 f'{NODE_A}')
    yield launch("arg/in-two-groups", '<group ns="x"><arg name="a" default="1"/>'
                 f'{NODE_A}</group><group ns="y">'
                 f'<arg name="a" default="2"/>{NODE_A}</group>')
    yield launch("arg/if-false", '<arg name="a" default="1" if="false"/>\n'
                 f'{NODE_A}')
    yield launch("arg/unless-false", '<arg name="a" default="1" unless="false"/>\n'
                 f'{NODE_A}')
    yield launch("arg/with-spaces", f'<arg name="a" default="one two"/>\n'
                 f'{NODE_A}')
    yield launch("arg/command-line-spaces", f'<arg name="a" default="x"/>\n'
                 f'{NODE_A}', args=("a:=one two",))
    yield launch("arg/bad-name", f'<arg name="a b" default="1"/>\n{node()}')
    yield launch("arg/no-name", f'<arg default="1"/>\n{node()}')


SUBSTITUTIONS = {
    "env": "$(env PROBE_V)",
    "env-missing": "$(env PROBE_NOT_SET)",
    "optenv": "$(optenv PROBE_V)",
    "optenv-missing": "$(optenv PROBE_NOT_SET)",
    "optenv-default": "$(optenv PROBE_NOT_SET fallback)",
    "optenv-default-spaces": "$(optenv PROBE_NOT_SET a default with spaces)",
    "optenv-set-default": "$(optenv PROBE_V fallback)",
    "find": "$(find probe)",
    "find-missing": "$(find no_such_package)",
    "arg": "$(arg a)",
    "two-in-one": "$(arg a)-$(env PROBE_V)",
    "eval-number": "$(eval 1 + 2)",
    "eval-nospace": "$(eval 1+2)",
    "eval-string": "$(eval 'x' * 3)",
    "eval-arg-bare": "$(eval a + '!')",
    "eval-arg-call": "$(eval arg('a') + '?')",
    "eval-compare": "$(eval arg('a') == 'va')",
    "eval-true": "$(eval true and not false)",
    "eval-env": "$(eval env('PROBE_V'))",
    "eval-optenv": "$(eval optenv('PROBE_NOT_SET', 'dflt'))",
    "eval-find": "$(eval find('probe') != '')",
    "eval-dirname": "$(eval dirname() != '')",
    "eval-math": "$(eval int(7 / 2))",
    "eval-mixed": "x$(eval 1+1)",
    "eval-import": "$(eval __import__('os').getcwd())",
    "eval-undefined": "$(eval nope + 1)",
    "eval-syntax": "$(eval 1 +)",
    "anon-same": "$(anon a)=$(anon a)",
    "dollar-plain": "cost$5",
    "unknown": "$(nope x)",
    "unclosed": "$(arg a",
    "arg-extra": "$(arg a b)",
    "env-two-words": "$(env PROBE_V extra)",
    "dirname": "$(dirname)",
    "nested-dirname": "$(dirname)/sub",
}


def substitutions() -> Iterator[dict[str, Any]]:
    for label, text in SUBSTITUTIONS.items():
        args = f'args="{text}"'
        yield launch(f"subst/{label}", f'<arg name="a" default="va"/>\n{node(attrs=" " + args)}',
                     env={"PROBE_V": "from env"})
        if label in ("env", "arg", "optenv-default-spaces", "eval-number", "eval-arg-bare",
                     "find", "dirname"):
            yield launch(f"subst/{label}-in-param", '<arg name="a" default="va"/>\n'
                         f'<param name="p" value="{text}"/>\n{node()}',
                         env={"PROBE_V": "from env"})


def groups() -> Iterator[dict[str, Any]]:
    bodies = {
        "ns-relative": f'<group ns="g">{node()}</group>',
        "ns-absolute": f'<group ns="/g">{node()}</group>',
        "ns-nested": f'<group ns="a"><group ns="b">{node()}</group></group>',
        "ns-nested-absolute": f'<group ns="a"><group ns="/b">{node()}</group></group>',
        "ns-trailing-slash": f'<group ns="g/">{node()}</group>',
        "ns-empty": f'<group ns="">{node()}</group>',
        "ns-private": f'<group ns="~p">{node()}</group>',
        "no-ns": f"<group>{node()}</group>",
        "if-false": f'<group if="false">{node()}</group>{node("m")}',
        "unless-true": f'<group unless="true">{node()}</group>{node("m")}',
        "if-bad": f'<group if="perhaps">{node()}</group>',
        "clear-params": '<param name="g/x" value="1"/><param name="y" value="2"/>'
                        f'<group ns="g" clear_params="true">{node()}</group>',
        "clear-params-no-ns": f'<group clear_params="true">{node()}</group>',
        "ns-with-arg": f'<arg name="n" default="robot"/><group ns="$(arg n)">{node()}</group>',
        "ns-bad-name": f'<group ns="a b">{node()}</group>',
        "unknown-attribute": f'<group nss="g">{node()}</group>',
        "param-and-node": f'<group ns="g"><param name="x" value="1"/>{node()}</group>',
        "node-ns-in-group": f'<group ns="g">{NODE_NS_H}</group>',
        "node-absolute-ns-in-group": f'<group ns="g">{NODE_NS_ABS_H}</group>',
    }
    for label, body in bodies.items():
        yield launch(f"group/{label}", body)


def nodes() -> Iterator[dict[str, Any]]:
    attrs = {
        "args-words": ' args="a b  c"',
        "args-quoted": ' args="a \'b c\' &quot;d e&quot;"',
        "args-empty": ' args=""',
        "ns-relative": ' ns="g"',
        "ns-absolute": ' ns="/g"',
        "ns-nested": ' ns="a/b"',
        "ns-trailing": ' ns="g/"',
        "output-screen": ' output="screen"',
        "output-log": ' output="log"',
        "output-bad": ' output="file"',
        "cwd-node": ' cwd="node"',
        "cwd-ros-home": ' cwd="ROS_HOME"',
        "cwd-bad": ' cwd="elsewhere"',
        "launch-prefix": ' launch-prefix="env PROBE_PREFIXED=1"',
        "respawn-false": ' respawn="false"',
        "required": ' required="true"',
        "required-bad": ' required="sometimes"',
        "respawn-and-required": ' respawn="true" required="true"',
        "clear-params": ' clear_params="true"',
        "if-false": ' if="false"',
        "unless-false": ' unless="false"',
        "if-and-unless": ' if="true" unless="false"',
        "unknown-attribute": ' colour="red"',
        "machine-missing": ' machine="nowhere"',
        "name-with-slash": "",
        "name-private": "",
        "type-missing": "",
        "package-missing": "",
        "no-name": "",
    }
    special = {
        "name-with-slash": '<node name="a/b" pkg="probe" type="probe.py"/>',
        "name-private": '<node name="~n" pkg="probe" type="probe.py"/>',
        "type-missing": '<node name="n" pkg="probe" type="nothing.py"/>',
        "package-missing": '<node name="n" pkg="no_such_pkg" type="probe.py"/>',
        "no-name": '<node pkg="probe" type="probe.py"/>',
    }
    for label, text in attrs.items():
        yield launch(f"node/{label}", special.get(label) or node(attrs=text))
    yield launch("node/respawn", node(attrs=' respawn="true"'), stop_after=3.0)
    yield launch("node/respawn-delay", node(attrs=' respawn="true" respawn_delay="10"'),
                 stop_after=3.0)
    # (a ends a second after it starts, b waits longer than that to respawn: nothing races)
    yield launch("node/required-ends-launch",
                 node("a", attrs=' required="true"',
                      body='<env name="PROBE_SLEEP" value="1"/>') +
                 node("b", attrs=' respawn="true" respawn_delay="5"'), stop_after=8.0)
    yield launch("node/two-same-name", node() + node())
    yield launch("node/same-name-other-ns", node() + node(attrs=' ns="g"'))
    yield launch("node/exits-nonzero", node(attrs=' respawn="false"'), env={"PROBE_EXIT": "3"})
    yield launch("node/machine", '<machine name="here" address="localhost"/>' +
                 node(attrs=' machine="here"'))
    yield launch("node/machine-default", '<machine name="here" address="localhost" '
                 'default="true"/>' + node())
    yield launch("node/machine-env", '<machine name="here" address="localhost">'
                 '<env name="PROBE_M" value="1"/></machine>' + node(attrs=' machine="here"'))
    yield launch("node/machine-declared-after", node(attrs=' machine="here"') +
                 '<machine name="here" address="localhost"/>')
    yield launch("node/machine-in-include", '<include file="$(dirname)/machines.launch"/>' +
                 node(attrs=' machine="here"'),
                 files={"machines.launch": '<launch><machine name="here" '
                                           'address="localhost"/></launch>\n'})
    yield launch("node/anon-name", '<node name="$(anon n)" pkg="probe" type="probe.py"/>')
    yield launch("node/test-tag", node() + '<test test-name="t" pkg="probe" type="probe.py"/>')
    yield launch("node/test-tag-only", '<test test-name="t" pkg="probe" type="probe.py"/>')
    yield launch("node/test-bad-attribute",
                 node() + '<test test-name="t" pkg="probe" type="probe.py" respawn="true"/>')


def remaps() -> Iterator[dict[str, Any]]:
    bodies = {
        "top": f'<remap from="a" to="b"/>{node()}',
        "after-node": f'{node()}<remap from="a" to="b"/>',
        "in-group": f'<group><remap from="a" to="b"/>{node()}</group>{node("m")}',
        "in-group-ns": f'<group ns="g"><remap from="a" to="b"/>{node()}</group>',
        "in-node": node(body='<remap from="a" to="b"/>'),
        "top-and-node": '<remap from="a" to="top"/>' + node(body='<remap from="a" to="own"/>'),
        "twice": f'<remap from="a" to="b"/><remap from="a" to="c"/>{node()}',
        "twice-in-node": node(body='<remap from="a" to="b"/><remap from="a" to="c"/>'),
        "private": node(body='<remap from="~a" to="b"/>'),
        "global": node(body='<remap from="/a" to="/b"/>'),
        "if-false": node(body='<remap from="a" to="b" if="false"/>'),
        "unless-false": node(body='<remap from="a" to="b" unless="false"/>'),
        "missing-to": node(body='<remap from="a"/>'),
        "bad-name": node(body='<remap from="a b" to="c"/>'),
        "with-arg": '<arg name="t" default="target"/>' + node(body='<remap from="a" '
                                                               'to="$(arg t)"/>'),
        "group-then-node": '<group><remap from="a" to="g"/>' +
                           node(body='<remap from="b" to="n"/>') + "</group>",
    }
    for label, body in bodies.items():
        yield launch(f"remap/{label}", body)


def environment() -> Iterator[dict[str, Any]]:
    bodies = {
        "top": f'<env name="PROBE_E" value="1"/>{node()}',
        "after-node": f'{node()}<env name="PROBE_E" value="1"/>',
        "in-group": f'<group><env name="PROBE_E" value="1"/>{node()}</group>{node("m")}',
        "in-node": node(body='<env name="PROBE_E" value="1"/>'),
        "node-over-top": '<env name="PROBE_E" value="top"/>' +
                         node(body='<env name="PROBE_E" value="own"/>'),
        "if-false": node(body='<env name="PROBE_E" value="1" if="false"/>'),
        "if-true": node(body='<env name="PROBE_E" value="1" if="true"/>'),
        "unless-true": f'<env name="PROBE_E" value="1" unless="true"/>{node()}',
        "from-arg": '<arg name="v" default="x"/>' +
                    node(body='<env name="PROBE_E" value="$(arg v)"/>'),
        "empty-value": node(body='<env name="PROBE_E" value=""/>'),
        "missing-value": node(body='<env name="PROBE_E"/>'),
        "overrides-shell": node(body='<env name="PROBE_V" value="launch"/>'),
        "shell-passes": node(),
        "ros-namespace": node(attrs=' ns="g"', body='<env name="ROS_NAMESPACE" value="/x"/>'),
    }
    for label, body in bodies.items():
        yield launch(f"env/{label}", body, env={"PROBE_V": "shell"})


INCLUDED = """<launch>
  <arg name="a" default="inner"/>
  <param name="inc/p" value="$(arg a)"/>
  <node name="inc" pkg="probe" type="probe.py" args="$(arg a) $(dirname)"/>
</launch>
"""
INCLUDED_REQUIRED = """<launch>
  <arg name="a"/>
  <node name="inc" pkg="probe" type="probe.py" args="$(arg a)"/>
</launch>
"""
NESTED = """<launch>
  <arg name="a" default="mid"/>
  <include file="$(dirname)/inc.launch"><arg name="a" value="$(arg a)-deeper"/></include>
</launch>
"""


def includes() -> Iterator[dict[str, Any]]:
    files = {"inc.launch": INCLUDED, "req.launch": INCLUDED_REQUIRED, "sub/nested.launch": NESTED,
             "sub/inc.launch": INCLUDED}
    bodies = {
        "plain": '<include file="$(dirname)/inc.launch"/>',
        "arg": '<include file="$(dirname)/inc.launch"><arg name="a" value="given"/></include>',
        "arg-default": '<include file="$(dirname)/inc.launch"><arg name="a" default="d"/>'
                       '</include>',
        "ns": '<include file="$(dirname)/inc.launch" ns="robot"/>',
        "ns-absolute": '<group ns="g"><include file="$(dirname)/inc.launch" ns="/r"/></group>',
        "in-group": '<group ns="g"><include file="$(dirname)/inc.launch"/></group>',
        "clear-params": '<param name="robot/inc/x" value="1"/>'
                        '<include file="$(dirname)/inc.launch" ns="robot" clear_params="true"/>',
        "clear-params-no-ns": '<include file="$(dirname)/inc.launch" clear_params="true"/>',
        "pass-all-args": '<arg name="a" default="outer"/>'
                         '<include file="$(dirname)/inc.launch" pass_all_args="true"/>',
        "pass-all-args-override": '<arg name="a" default="outer"/>'
                                  '<include file="$(dirname)/inc.launch" pass_all_args="true">'
                                  '<arg name="a" value="own"/></include>',
        "required-arg-given": '<include file="$(dirname)/req.launch">'
                              '<arg name="a" value="r"/></include>',
        "required-arg-missing": '<include file="$(dirname)/req.launch"/>',
        "unknown-arg": '<include file="$(dirname)/inc.launch"><arg name="zzz" value="1"/>'
                       '</include>',
        "nested": '<include file="$(dirname)/sub/nested.launch"/>',
        "nested-arg": '<include file="$(dirname)/sub/nested.launch"><arg name="a" value="top"/>'
                      '</include>',
        "if-false": '<include file="$(dirname)/inc.launch" if="false"/>',
        "unless-false": '<include file="$(dirname)/inc.launch" unless="false"/>',
        "missing-file": '<include file="$(dirname)/nothing.launch"/>',
        "find": '<include file="$(find probe)/launch/probe.launch"/>',
        "twice": '<include file="$(dirname)/inc.launch" ns="a"/>'
                 '<include file="$(dirname)/inc.launch" ns="b"/>',
        "twice-same-ns": '<include file="$(dirname)/inc.launch"/>'
                         '<include file="$(dirname)/inc.launch"/>',
        "env-inside": '<include file="$(dirname)/inc.launch">'
                      '<env name="PROBE_E" value="1"/></include>',
        "arg-leaks-not": '<include file="$(dirname)/inc.launch"/>'
                         + node("after", attrs=' args="$(arg a)"'),
        "command-line-not-passed": '<include file="$(dirname)/inc.launch"/>',
    }
    for label, body in bodies.items():
        args = ("a:=cli",) if label == "command-line-not-passed" else ()
        yield launch(f"include/{label}", body, files=files, args=args)


def errors() -> Iterator[dict[str, Any]]:
    texts = {
        "not-xml": "<launch><node",
        "wrong-root": "<robot/>",
        "unknown-tag": "<launch><nodes/></launch>",
        "text-in-launch": "<launch>hello</launch>",
        "empty": "",
        "comment-only": "<launch><!-- nothing --></launch>",
        "deprecated-attribute": '<launch deprecated="old"/>',
    }
    for label, text in texts.items():
        yield {"name": f"ros1/error/{label}", "files": {"main.launch": text}}
    yield launch("error/master", f'<master auto="start"/>{node()}')
    yield launch("error/missing-launch-file", node(), main="nothing.launch")


def specs() -> Iterator[dict[str, Any]]:
    for family in (parameters, rosparams, arguments, substitutions, groups, nodes, remaps,
                   environment, includes, errors):
        yield from family()

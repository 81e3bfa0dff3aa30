import os
import sys

import pytest

from launcher.errors import LaunchError, ParseError, SubstitutionError
from launcher.runtime.context import LaunchContext
from tests.support.launch_text import evaluate


def ctx(configurations=None, environment=None):
    return LaunchContext(environment or {"PATH": os.environ["PATH"]}, configurations or {})


def test_var_and_its_roslaunch_spelling():
    context = ctx({"robot": "r2"})
    assert evaluate("$(var robot)-", context) + evaluate("$(arg robot)", context,
                                                         roslaunch=True) == "r2-r2"


@pytest.mark.parametrize("text, spelling", [("$(arg robot)", "$(var"),
                                            ("$(find pkg)", "$(find-pkg-share"),
                                            ("$(optenv X d)", "$(env")])
def test_a_ros2_file_refuses_roslaunch_spellings_and_names_its_own(text, spelling):
    with pytest.raises(ParseError, match="that is roslaunch's") as info:
        evaluate(text, ctx({"robot": "r2"}))
    assert spelling in str(info.value)


def test_roslaunch_optenv_default_is_every_word_after_the_name():
    assert evaluate("$(optenv NOPE a default  with spaces)", ctx(), roslaunch=True) == \
        "a default with spaces"
    assert evaluate("$(optenv NOPE)", ctx(), roslaunch=True) == ""


@pytest.mark.parametrize("text, message", [
    ("$(arg a b)", "takes exactly one word in roslaunch, got 2"),
    ("$(env)", "takes exactly one word in roslaunch, got 0"),
    ("$(var a)", "unknown roslaunch substitution '$(var)'"),
    ("$(arg $(arg a))", "no '$' inside a substitution"),
    ("$(arg a", "unclosed '$(arg a': expected ')'"),
    ("x $(eval 1) y", "only as the whole attribute"),
])
def test_roslaunch_substitution_errors(text, message):
    with pytest.raises(ParseError) as info:
        evaluate(text, ctx({"a": "1"}), roslaunch=True)
    assert message in str(info.value)


def test_roslaunch_eval_is_the_whole_expression_with_its_names():
    context = ctx({"count": "3", "name": "bot"}, {"HOME_X": "/h", "PATH": os.environ["PATH"]})
    assert evaluate("$(eval 'x' * count)", context, roslaunch=True) == "xxx"  # typed arg
    assert evaluate("$(eval arg('name') + env('HOME_X'))", context, roslaunch=True) == "bot/h"
    assert evaluate("$(eval optenv('NOPE', 'd d') if true else 0)", context,
                    roslaunch=True) == "d d"
    with pytest.raises(SubstitutionError, match="may not hold '__'"):
        evaluate("$(eval count.__class__)", context, roslaunch=True)


def test_var_default_and_missing_with_suggestion():
    assert evaluate("$(var nope fallback)") == "fallback"
    with pytest.raises(SubstitutionError) as info:
        evaluate("$(var robto)", ctx({"robot": "x"}))
    assert "'robto' is not set" in str(info.value) and "did you mean 'robot'" in str(info.value)


def test_env_optenv_and_missing():
    context = ctx(environment={"HOME_X": "/h"})
    assert evaluate("$(env HOME_X)", context) == "/h"
    assert evaluate("$(env NOPE default)", context) == "default"
    with pytest.raises(SubstitutionError, match="environment variable 'NOPE' is not set"):
        evaluate("$(env NOPE)", context)


def test_eval_restricted_expressions():
    assert evaluate("$(eval '1 + 2 * 3')") == "7"
    assert evaluate("$(eval 'math.pi > 3 and 2 ** 3 == 8')") == "True"
    assert evaluate("$(eval '\"ab\".upper()')") == "AB"
    assert evaluate("$(eval '$(var n) * 2')", ctx({"n": "21"})) == "42"


@pytest.mark.parametrize("expression", [
    "__import__('os')", "().__class__", "open('x')", "[x for x in (1,)]", "lambda: 1",
    "'a'.__class__", "print(1)",
], ids=["import", "dunder", "open", "comprehension", "lambda", "str-dunder", "print"])
def test_eval_rejects_anything_else(expression):
    with pytest.raises(SubstitutionError, match=r"\$\(eval"):
        evaluate(f'$(eval "{expression}")')


def test_eval_that_does_not_evaluate():
    with pytest.raises(SubstitutionError, match="ZeroDivisionError"):
        evaluate("$(eval '1 / 0')")
    with pytest.raises(SubstitutionError, match="invalid expression"):
        evaluate("$(eval '1 +')")


def test_logic_substitutions():
    assert evaluate("$(not true)") == "false"
    assert evaluate("$(and true 1)") == "true"
    assert evaluate("$(or false 0)") == "false"
    assert evaluate("$(any false false true)") == "true"
    assert evaluate("$(all true true false)") == "false"
    assert evaluate("$(equals 1.0 1)") == "true"
    assert evaluate("$(equals True true)") == "true"
    assert evaluate("$(not-equals a b)") == "true"
    assert evaluate("$(if true yes no)") == "yes"
    assert evaluate("$(if false yes)") == ""
    with pytest.raises(SubstitutionError, match="expected true, false, 1 or 0"):
        evaluate("$(not maybe)")


def test_anon_is_stable_per_name_within_a_run():
    context = ctx()
    first, again, other = (evaluate(f"$(anon {n})", context) for n in ("a", "a", "b"))
    assert first == again and first != other and first.startswith("a_")


def test_command_output_keeps_trailing_newline():
    assert evaluate("$(command 'echo hi')") == "hi\n"


def test_command_failure_shows_stderr():
    with pytest.raises(SubstitutionError) as info:
        evaluate(f"$(command '{sys.executable} -c \"import sys; sys.exit(sys.stderr.write(\\'boom\\') and 3)\"')")
    assert "exit code 3" in str(info.value) and "boom" in str(info.value)


def test_command_stderr_modes(tmp_path):
    script = tmp_path / "warn.sh"
    script.write_text("#!/bin/sh\necho out; echo noise >&2\n")
    script.chmod(0o755)
    with pytest.raises(SubstitutionError, match="wrote to stderr"):
        evaluate(f"$(command '{script}')")
    assert evaluate(f"$(command '{script}' ignore)") == "out\n"
    assert "noise" in evaluate(f"$(command '{script}' capture)")
    with pytest.raises(SubstitutionError, match="must be one of"):
        evaluate(f"$(command '{script}' loud)")


def test_command_not_found():
    with pytest.raises(SubstitutionError, match="no executable 'no-such-program-x'"):
        evaluate("$(command 'no-such-program-x')")


def test_files(tmp_path):
    (tmp_path / "value.txt").write_text("content")
    context = ctx()
    context.files.push(tmp_path / "a.launch.yaml")
    assert evaluate("$(dirname)", context) == str(tmp_path)
    assert evaluate("$(filename)", context) == str(tmp_path / "a.launch.yaml")
    assert evaluate("$(file-content value.txt)", context) == "content"
    with pytest.raises(SubstitutionError, match="no file"):
        evaluate("$(file-content missing.txt)", context)
    assert evaluate("$(find-exec sh)", context).endswith("/sh")
    with pytest.raises(SubstitutionError, match="no executable 'nosuchexe'"):
        evaluate("$(find-exec nosuchexe)", context)


def test_unknown_substitution_suggests():
    with pytest.raises(ParseError, match=r"unknown substitution '\$\(vra\)' \(did you mean 'var'"):
        evaluate("$(vra x)")


def test_wrong_argument_count():
    with pytest.raises(LaunchError, match=r"\$\(var\) takes 1 to 2 arguments, got 3"):
        evaluate("$(var a b c)")

import pytest

from launcher.frontend.substitution_parser import Call, SubstitutionSyntaxError, parse_text


def test_plain_text_is_one_part():
    assert parse_text("hello world") == ("hello world",)


def test_dollar_without_parenthesis_is_literal():
    assert parse_text("cost $5 and $x") == ("cost $5 and $x",)


def test_escaped_dollar_is_literal():
    assert parse_text(r"\$(var x)") == ("$(var x)",)


def test_call_with_arguments_and_offset():
    parts = parse_text("a $(var name default) b")
    assert parts[0] == "a " and parts[2] == " b"
    call = parts[1]
    assert call.name == "var" and call.offset == 2
    assert call.args == (("name",), ("default",))


def test_nested_calls_and_quotes():
    (call,) = parse_text("$(command 'xacro $(find-pkg-share pkg)/x.xacro')")
    assert call.name == "command"
    (arg,) = call.args
    assert arg[0] == "xacro "
    assert isinstance(arg[1], Call) and arg[1].name == "find-pkg-share"
    assert arg[2] == "/x.xacro"


def test_double_quotes_escape_inner_quote():
    (call,) = parse_text(r'$(eval "\"a\" + b")')
    assert call.args == (('"a" + b',),)


def test_empty_quoted_argument_is_kept():
    (call,) = parse_text("$(var x '')")
    assert call.args == (("x",), ("",))


@pytest.mark.parametrize("text, offset", [("x $(var a", 2), ("$(", 0), ("$(var 'a)", 6)],
                         ids=["unclosed-call", "no-name", "unclosed-quote"])
def test_syntax_errors_point_at_the_offset(text, offset):
    with pytest.raises(SubstitutionSyntaxError) as info:
        parse_text(text)
    assert info.value.offset == offset

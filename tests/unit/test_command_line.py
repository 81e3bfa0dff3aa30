from launcher.description.command_line import join_command, split_command
from launcher.description.substitution import Text
from launcher.description.substitutions.configuration import LaunchConfiguration
from launcher.runtime.context import LaunchContext


def var(name):
    return LaunchConfiguration((Text(name),))


CONTEXT = LaunchContext({}, {"msg": "hello 'big' world", "path": "/a b/c"})


def test_plain_words_and_quotes():
    text = (Text("gz sim -v 4 'two words' \"x y\" a\\ b"),)
    assert split_command(CONTEXT, text) == ["gz", "sim", "-v", "4", "two words", "x y", "a b"]


def test_substitution_value_is_never_split():
    assert split_command(CONTEXT, (Text("ls "), var("path"))) == ["ls", "/a b/c"]


def test_quotes_span_a_substitution():
    text = (Text("sh -c 'echo "), var("msg"), Text("'"))
    assert split_command(CONTEXT, text) == ["sh", "-c", "echo hello 'big' world"]


def test_substitution_glues_to_adjacent_text():
    assert split_command(CONTEXT, (var("path"), Text("/bin x"))) == ["/a b/c/bin", "x"]


def test_shell_text_is_kept_whole():
    assert join_command(CONTEXT, (Text("echo "), var("msg"), Text(" | wc"))) == \
        "echo hello 'big' world | wc"

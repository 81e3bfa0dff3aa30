"""The byte protocol between a launch and its supervisor on another host: frames come out of a
stream cut anywhere, the chatter before the magic line is skipped, and what breaks the
protocol (a frame too long, an unknown kind, a body that is not its kind's) is an error."""

import struct

import pytest

from launcher import __version__
from launcher.errors import LaunchError
from launcher.runtime import remote_frames as frames
from launcher.runtime.remote_frames import (
    MAX_FRAME,
    MAX_OUTPUT,
    Decoder,
    Message,
    Output,
    ProtocolError,
    ProtocolMismatch,
)

HELLO = {"t": "hello", "launch": "ab12", "ping": 0.25, "silence": 0.75, "domain": 0,
         "graph": None}


def test_a_message_and_output_come_back_as_sent():
    data = frames.message(HELLO) + frames.output(7, frames.STDERR, b"\x00\xffraw")
    assert Decoder().feed(data) == [Message(HELLO), Output(7, 2, b"\x00\xffraw")]


def test_frames_cut_anywhere_come_out_whole_once_their_last_byte_is_in():
    data = frames.message({"t": "exited", "id": 3, "code": -2}) + frames.output(3, 1, b"x" * 70)
    decoder = Decoder()
    found = []
    for at in range(len(data)):
        found += decoder.feed(data[at:at + 1])
    assert found == [Message({"t": "exited", "id": 3, "code": -2}), Output(3, 1, b"x" * 70)]


def test_a_command_lines_undecodable_bytes_travel_and_come_back():
    word = b"caf\xe9".decode(errors="surrogateescape")  # (how Python reads argv on Linux)
    [found] = Decoder().feed(frames.message({"t": "start", "argv": [word]}))
    assert found.body["argv"] == [word]


def test_output_longer_than_a_frame_takes_goes_in_several():
    data = b"".join(bytes([i % 251]) for i in range(3 * MAX_OUTPUT + 5))
    found = Decoder().feed(frames.output(1, 1, data))
    assert [len(f.data) for f in found] == [MAX_OUTPUT] * 3 + [5]
    assert b"".join(f.data for f in found) == data


def test_no_output_is_no_frame():
    assert frames.output(1, 1, b"") == b""


def test_the_magic_line_names_the_protocol_and_the_launcher():
    assert frames.magic_line() == f"launcher-remote 1 {__version__}\n".encode()
    assert frames.parse_magic(frames.magic_line()) == (1, __version__)


@pytest.mark.parametrize("line", [b"launcher-remote\n", b"launcher-remote x 1.0\n",
                                  b"Welcome to Ubuntu\n", b"launcher-remote 1 0.1 extra\n", b""])
def test_other_lines_are_not_the_magic_one(line):
    assert frames.parse_magic(line) is None


def test_chatter_before_the_magic_line_is_skipped_and_kept_for_the_log():
    decoder = Decoder(magic=True)
    data = b"Welcome\r\nenv-loader: sourcing ws\n" + frames.magic_line() + frames.message(
        {"t": "ready"})
    assert decoder.feed(data[:20]) == []
    assert decoder.feed(data[20:]) == [Message({"t": "ready"})]
    assert decoder.noise == [b"Welcome", b"env-loader: sourcing ws"]
    assert decoder.peer == (1, __version__)


def test_frames_right_after_a_magic_line_cut_in_two_are_read():
    decoder = Decoder(magic=True)
    data = frames.magic_line() + frames.message({"t": "ping"})
    assert decoder.feed(data[:10]) == [] and decoder.peer is None
    assert decoder.feed(data[10:]) == [Message({"t": "ping"})]


def test_an_endless_line_before_the_magic_one_is_cut_not_held():
    decoder = Decoder(magic=True)
    decoder.feed(b"y" * (frames.MAX_NOISE_LINE + 1))
    assert [len(n) for n in decoder.noise] == [frames.MAX_NOISE_LINE + 1]
    assert decoder.feed(b"\n" + frames.magic_line() + frames.message({"t": "ping"})) == [
        Message({"t": "ping"})]


def test_another_protocol_is_a_mismatch_naming_both():
    with pytest.raises(ProtocolMismatch) as caught:
        Decoder(magic=True).feed(b"launcher-remote 2 9.0\n")
    assert (caught.value.protocol, caught.value.version) == (2, "9.0")
    assert "remote protocol 2 (launcher 9.0)" in str(caught.value)
    assert f"this one speaks 1 (launcher {__version__})" in str(caught.value)


def frame(kind: bytes, body: bytes) -> bytes:
    return struct.pack(">I", len(body) + 1) + kind + body


@pytest.mark.parametrize(("data", "said"), [
    (struct.pack(">I", MAX_FRAME + 1) + b"J", f"frames are 1 to {MAX_FRAME}"),
    (struct.pack(">I", 0) + b"J", "frames are 1 to"),
    (frame(b"X", b"{}"), "unknown kind b'X'; kinds are J and O"),
    (frame(b"J", b"{not json"), "a J frame that is not JSON"),
    (frame(b"J", b"\xff\xfe"), "a J frame that is not JSON"),
    (frame(b"J", b"[1, 2]"), "not an object with a \"t\" string"),
    (frame(b"J", b'{"id": 7}'), "not an object with a \"t\" string"),
    (frame(b"O", b"\x00\x00"), "an O frame of 2 bytes; its head alone is 5"),
    (frame(b"O", struct.pack(">IB", 1, 3) + b"x"), "stream 3; streams are 1 and 2"),
    (frame(b"O", struct.pack(">IB", 1, 1) + b"x" * (MAX_OUTPUT + 1)),
     f"{MAX_OUTPUT + 1} bytes of output; at most {MAX_OUTPUT}"),
], ids=["too long", "empty", "unknown kind", "bad JSON", "not UTF-8", "not an object", "no t",
        "short output head", "bad stream", "too much output"])
def test_what_breaks_the_protocol_is_a_protocol_error(data, said):
    with pytest.raises(ProtocolError) as caught:
        Decoder().feed(data)
    assert said in str(caught.value)


def test_a_frame_too_long_is_refused_from_its_header_alone():
    """(not after 16 MiB more have been waited for)"""
    with pytest.raises(ProtocolError):
        Decoder().feed(struct.pack(">I", MAX_FRAME + 1))


def test_a_message_too_long_to_send_is_refused():
    with pytest.raises(ProtocolError, match="at most 16777216 go in one"):
        frames.message({"t": "start", "files": [{"path": "p", "text": "x" * MAX_FRAME}]})


def test_a_protocol_error_is_a_launch_error():
    assert issubclass(ProtocolError, LaunchError)

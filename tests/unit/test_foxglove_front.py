"""The foxglove bridge's front speaks for clients of the protocol's old name."""

from launcher.nodes.foxglove.front import answered_as_offered, offered_as_sdk

REQUEST = (b"GET /?token=t HTTP/1.1\r\nHost: x\r\nsec-websocket-protocol: %s\r\n"
           b"Sec-WebSocket-Key: k\r\n\r\n")


def test_a_request_offering_the_old_name_alone_offers_the_sdks():
    head, renamed = offered_as_sdk(REQUEST % b"foxglove.websocket.v1")
    assert renamed and head == REQUEST % b"foxglove.sdk.v1"


def test_a_request_offering_the_sdks_name_is_passed_as_it_is():
    for offered in (b"foxglove.sdk.v1", b"foxglove.sdk.v1, foxglove.websocket.v1", b"other"):
        assert offered_as_sdk(REQUEST % offered) == (REQUEST % offered, False)


def test_the_answer_names_the_protocol_as_offered_and_keeps_what_follows_it():
    answer = (b"HTTP/1.1 101 Switching Protocols\r\nSec-WebSocket-Protocol: foxglove.sdk.v1\r\n"
              b"\r\n\x81\x05hello")
    assert answered_as_offered(answer) == answer.replace(b"foxglove.sdk.v1",
                                                         b"foxglove.websocket.v1")

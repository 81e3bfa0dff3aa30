"""An independent action client: raw Zenoh and rosbags' CDR, none of launcher's code.

It finds the action's endpoints as any rmw_zenoh program would, from the graph's liveliness
tokens (`@ros2_lv/<domain>/…/SS/…/%fibonacci%_action%send_goal/<type>/<hash>/…`), sends a
Fibonacci goal on the send_goal service's key, hears feedback and status on their topics' keys,
and asks for the result. It prints one line per finding, for the test to read. Run with
ZENOH_SESSION_CONFIG_URI from `launcher env --zenoh`.
"""

from __future__ import annotations

import os
import sys
import threading
import time
import uuid

import zenoh
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

ACTION = "example_interfaces/action/Fibonacci"
PARTS = {"Goal": "int32 order", "Result": "int32[] sequence", "Feedback": "int32[] sequence"}
WRAPPERS = {  # what rosidl makes of an action (written out here, not taken from launcher)
    "SendGoal_Request": f"unique_identifier_msgs/UUID goal_id\n{ACTION}_Goal goal",
    "SendGoal_Response": "bool accepted\nbuiltin_interfaces/Time stamp",
    "GetResult_Request": "unique_identifier_msgs/UUID goal_id",
    "GetResult_Response": f"int8 status\n{ACTION}_Result result",
    "FeedbackMessage": f"unique_identifier_msgs/UUID goal_id\n{ACTION}_Feedback feedback",
}


def typestore():
    store = get_typestore(Stores.ROS2_JAZZY)
    for part, text in {**PARTS, **WRAPPERS}.items():
        store.register(get_types_from_msg(text, f"{ACTION}_{part}"))
    return store


def endpoints(session, name: str) -> dict[str, tuple[str, str, str]]:
    """{what: (kind, dds type, hash)} of the action's services and topics, from the tokens."""
    found = {}
    for reply in session.liveliness().get("@ros2_lv/**", timeout=3.0):
        parts = str(reply.ok.key_expr).split("/")
        # @ros2_lv/<domain>/<zid>/<nid>/<eid>/<kind>/<enclave>/<ns>/<node>/<name>/<type>/<hash>
        if len(parts) < 12 or parts[5] not in ("SS", "MP"):
            continue
        topic = parts[9].replace("%", "/")
        if topic.startswith(f"/{name}/_action/"):
            found[topic.rsplit("/", 1)[1]] = (parts[5], parts[10], parts[11])
    return found


def main() -> int:
    config = zenoh.Config.from_file(os.environ["ZENOH_SESSION_CONFIG_URI"])
    session = zenoh.open(config)
    try:
        return use(session)
    finally:
        session.close()


def use(session) -> int:
    store = typestore()
    domain = os.environ.get("ROS_DOMAIN_ID", "0")
    time.sleep(1.0)
    found = endpoints(session, "fibonacci")
    for what in sorted(found):
        print("endpoint", what, *found[what], flush=True)
    needed = ("send_goal", "get_result", "cancel_goal", "feedback", "status")
    if not all(w in found for w in needed):
        return 1

    def key(what: str) -> str:
        _, dds, hash_ = found[what]
        return f"{domain}/fibonacci/_action/{what}/{dds}/{hash_}"

    feedback: list[list[int]] = []
    statuses: list[list[int]] = []
    ended = threading.Event()

    def on_feedback(sample) -> None:
        message = store.deserialize_cdr(sample.payload.to_bytes(),
                                        f"{ACTION}_FeedbackMessage")
        feedback.append([int(n) for n in message.feedback.sequence])

    def on_status(sample) -> None:
        message = store.deserialize_cdr(sample.payload.to_bytes(),
                                        "action_msgs/msg/GoalStatusArray")
        statuses.append([s.status for s in message.status_list])
        if any(s.status == 4 for s in message.status_list):
            ended.set()

    subscribers = [session.declare_subscriber(key("feedback"), on_feedback),
                   session.declare_subscriber(key("status"), on_status)]
    time.sleep(0.5)
    UUID = store.types["unique_identifier_msgs/msg/UUID"]
    Goal = store.types[f"{ACTION}_Goal"]
    goal_id = UUID(uuid=__import__("numpy").frombuffer(uuid.uuid4().bytes, dtype="uint8"))
    request = store.types[f"{ACTION}_SendGoal_Request"](goal_id=goal_id, goal=Goal(order=5))
    payload = bytes(store.serialize_cdr(request, f"{ACTION}_SendGoal_Request"))
    for reply in session.get(key("send_goal"), payload=payload, timeout=5.0):
        response = store.deserialize_cdr(reply.ok.payload.to_bytes(),
                                         f"{ACTION}_SendGoal_Response")
        print("accepted", response.accepted, flush=True)
    payload = bytes(store.serialize_cdr(
        store.types[f"{ACTION}_GetResult_Request"](goal_id=goal_id), f"{ACTION}_GetResult_Request"))
    for reply in session.get(key("get_result"), payload=payload, timeout=10.0):
        response = store.deserialize_cdr(reply.ok.payload.to_bytes(),
                                         f"{ACTION}_GetResult_Response")
        print("result", response.status, [int(n) for n in response.result.sequence], flush=True)
    ended.wait(3.0)
    # feedback and status travel on keys of their own: the last feedback may land after the
    # status that says the goal succeeded (and callbacks of two keys may interleave)
    deadline = time.monotonic() + 3.0
    while time.monotonic() < deadline and not (feedback and len(max(feedback, key=len)) >= 6):
        time.sleep(0.05)
    print("feedback", max(feedback, key=len) if feedback else None, flush=True)
    print("statuses", statuses[-1] if statuses else None, flush=True)
    for subscriber in subscribers:
        subscriber.undeclare()
    return 0


if __name__ == "__main__":
    sys.exit(main())

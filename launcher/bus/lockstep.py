"""Lockstep: a sim that runs as fast as the nodes that follow its clock, and no faster.

A sim run with `--lockstep` (the leader) steps one tick at a time, unpaced. After each tick it
publishes its clock and waits until every member of the lockstep has answered for that time:
  - a node on sim time (a follower), once it has done all that time asked of it (its timers
    due by then have run, and what they published has been sent): it answers when its
    executor has nothing left to do;
  - a bridge (a relay), once every follower's answer has come through it: what the followers
    published before answering has reached the bridge and been forwarded.
An answer says how far each of the member's publishers has got (its last sequence number), so
the one who waits knows what is still on its way: the leader steps on only once all that the
members sent has arrived, and applies it before the next tick. So a node's command lands on
the same step whatever the machine's load, and a run repeats exactly.

With no follower present, the sim's time stands still (its services still answer): time moves
when a node on sim time joins. A member that does not answer within PATIENCE is warned about
and no longer waited for until it answers again: no node can hang the sim.

The keys (one graph per router, so no domain is needed):
  @launcher/lockstep/leader/<world>                    the leader's liveliness token
  @launcher/lockstep/member/<node|relay>/<zid>/<nid>/<node name>   a member's token
  @launcher/lockstep/ack/<node|relay>/<zid>/<nid>/<node name>      its answers: JSON
      {"t": ns, "sent": [[key, gid hex, sequence], …]} (names with '/' written '%')
"""

from __future__ import annotations

import json
import threading
import time
from collections import Counter
from collections.abc import Callable
from typing import Any

import zenoh

from launcher.bus import keys
from launcher.bus.host import Host, direct

ROOT = "@launcher/lockstep"
LEADER, MEMBER, ACK = f"{ROOT}/leader", f"{ROOT}/member", f"{ROOT}/ack"
NODE, RELAY = "node", "relay"
PATIENCE = 2.0  # s of wall time a member is waited for before the sim goes on without it


class Ledger:
    """What this process has received of each publisher (its last sequence number), for the
    topics it subscribes to: kept while a lockstep waits here (the leader's and the relays'
    processes)."""

    def __init__(self) -> None:
        self.enabled = False
        self.subscribed: Counter[str] = Counter()  # key -> subscriptions to it
        self._received: dict[bytes, int] = {}
        self._listeners: list[Callable[[], None]] = []

    def subscribe(self, key: str) -> None:
        self.subscribed[key] += 1

    def unsubscribe(self, key: str) -> None:
        self.subscribed[key] -= 1
        if self.subscribed[key] <= 0:
            del self.subscribed[key]

    def note(self, attachment: Any) -> None:
        """A sample has been received (delivered, or queued for its callback)."""
        fields = keys.parse_attachment(attachment.to_bytes()) if attachment is not None \
            else None
        if fields is None:
            return
        sequence, _, gid = fields
        if sequence > self._received.get(gid, 0):
            self._received[gid] = sequence
        for listener in self._listeners:
            listener()

    def listen(self, listener: Callable[[], None]) -> None:
        """`listener()` after each sample noted (on the receiving thread)."""
        self._listeners.append(listener)

    def landed(self, sent: list[list[Any]]) -> bool:
        """Whether everything in `sent` ([key, gid hex, sequence], a member's answer) that
        this process subscribes to has been received."""
        return all(self._received.get(bytes.fromhex(gid), 0) >= sequence
                   for key, gid, sequence in sent if key in self.subscribed)


LEDGER = Ledger()


def sent_by(host: Host) -> list[list[Any]]:
    """[key, gid hex, last sequence] of each publisher of the node that has published."""
    return [[p.key, p.gid.hex(), p.sent] for p in host.entities
            if getattr(p, "sent", 0)]


class _Watch:
    """Whether a lockstep leader is on the graph; `changed(on)` on the node's executor when
    that changes (a member joins while there is one)."""

    def __init__(self, host: Host, changed: Callable[[bool], None]) -> None:
        self.host, self._changed = host, changed
        self.leaders: set[str] = set()
        self._subscriber = host.session.liveliness().declare_subscriber(
            f"{LEADER}/**", direct(self._on_token), history=True)

    def _on_token(self, sample: zenoh.Sample) -> None:
        self.host.enqueue(self._update, str(sample.key_expr), sample.kind == zenoh.SampleKind.PUT)

    def _update(self, key: str, alive: bool) -> None:
        was = bool(self.leaders)
        (self.leaders.add if alive else self.leaders.discard)(key)
        if bool(self.leaders) != was:
            self._changed(bool(self.leaders))

    def close(self) -> None:
        self._subscriber.undeclare()


class _Membership:
    """A member's token and the publisher of its answers, while a leader is there."""

    def __init__(self, host: Host, role: str) -> None:
        self.host, self.role = host, role
        node = f"{host.namespace.rstrip('/')}/{host.name}"
        self.name = f"{role}/{host.session.zid()}/{host.node_id}/{keys.mangle(node)}"
        self._token: Any = None
        self._answers: Any = None
        self.watch = _Watch(host, self._on_leader)

    @property
    def active(self) -> bool:
        return self._token is not None

    def _on_leader(self, present: bool) -> None:
        if present and self._token is None:
            self._answers = self.host.session.declare_publisher(
                f"{ACK}/{self.name}", reliability=zenoh.Reliability.RELIABLE,
                congestion_control=zenoh.CongestionControl.BLOCK)
            self._token = self.host.session.liveliness().declare_token(
                f"{MEMBER}/{self.name}")
            self.joined()
        elif not present and self._token is not None:
            self._leave()

    def joined(self) -> None:
        """The leader is there and this member has joined."""

    def answer(self, time_ns: int) -> None:
        """Tell the leader this member is done with `time_ns`, and what it has sent."""
        self._answers.put(json.dumps({"t": time_ns, "sent": sent_by(self.host)}))

    def _leave(self) -> None:
        for item in (self._token, self._answers):
            item.undeclare()
        self._token = self._answers = None

    def close(self) -> None:
        self.watch.close()
        if self._token is not None:
            self._leave()

    def destroy(self) -> None:
        """(its node's entities are destroyed with it)"""
        if self.host.forget(self):
            self.close()


class Follower(_Membership):
    """A node on sim time: told each `/clock` it handles, it answers for that time once its
    executor is idle (`caught_up`)."""

    def __init__(self, host: Host) -> None:
        super().__init__(host, NODE)
        self._time: int | None = None
        self._answered: int | None = None

    def clock(self, time_ns: int) -> None:
        if time_ns == self._answered:  # said again: the leader is still waiting (a member
            self._answered = None  # that joined since may have missed the answer)
        self._time = time_ns

    def caught_up(self) -> None:
        """The executor has nothing left to do: answer for the last clock, once."""
        if self.active and self._time is not None and self._time != self._answered:
            self._answered = self._time
            self.answer(self._time)


class _Answers:
    """The members on the graph and their last answers (kept on the executor's thread)."""

    def __init__(self, host: Host, roles: str, changed: Callable[[], None]) -> None:
        self.host, self._changed = host, changed
        self.members: dict[str, str] = {}  # name -> role
        self.last: dict[str, tuple[int, list[list[Any]]]] = {}  # name -> (t, sent)
        self.repeated = False  # a member answered again for the same time (asked again)
        self._tokens = host.session.liveliness().declare_subscriber(
            f"{MEMBER}/{roles}", direct(self._on_token), history=True)
        self._acks = host.session.declare_subscriber(f"{ACK}/{roles}", direct(self._on_ack))

    def _on_token(self, sample: zenoh.Sample) -> None:
        name = str(sample.key_expr)[len(MEMBER) + 1:]
        self.host.enqueue(self._member, name, sample.kind == zenoh.SampleKind.PUT)

    def _member(self, name: str, alive: bool) -> None:
        if alive:
            self.members[name] = name.split("/", 1)[0]
        else:
            self.members.pop(name, None)
            self.last.pop(name, None)
        self._changed()

    def _on_ack(self, sample: zenoh.Sample) -> None:
        name = str(sample.key_expr)[len(ACK) + 1:]
        try:
            answer = json.loads(sample.payload.to_bytes())
            entry = (int(answer["t"]), [list(s) for s in answer["sent"]])
        except (ValueError, KeyError, TypeError):
            return  # not an answer: ignored
        self.host.enqueue(self._answer, name, entry)

    def _answer(self, name: str, entry: tuple[int, list[list[Any]]]) -> None:
        previous = self.last.get(name)
        self.repeated = self.repeated or (previous is not None and previous[0] == entry[0])
        self.last[name] = entry
        self._changed()

    def done(self, name: str, time_ns: int) -> bool:
        """The member has answered for `time_ns` (or later), and what it sent has arrived."""
        entry = self.last.get(name)
        return entry is not None and entry[0] >= time_ns and LEDGER.landed(entry[1])

    def close(self) -> None:
        self._tokens.undeclare()
        self._acks.undeclare()


class Relay(_Membership):
    """A bridge: it answers for a time once every follower has answered for it and what they
    sent has come through (forwarded, as the bridge forwards on receipt)."""

    def __init__(self, host: Host) -> None:
        super().__init__(host, RELAY)
        self._followers: _Answers | None = None
        self._answered: int | None = None
        self._poked = False
        self._lock = threading.Lock()

    def joined(self) -> None:
        LEDGER.enabled = True
        if self._followers is None:
            self._followers = _Answers(self.host, f"{NODE}/**", self._check)
            LEDGER.listen(self._poke)

    def _poke(self) -> None:
        """A sample came (on its receiving thread): look again, on the executor, once."""
        with self._lock:
            if self._poked:
                return
            self._poked = True
        self.host.enqueue(self._check)

    def _check(self) -> None:
        with self._lock:
            self._poked = False
        answers = self._followers
        if not self.active or answers is None or not answers.members:
            return
        times = [answers.last[name][0] if name in answers.last else None
                 for name in answers.members]
        if None in times:
            return
        time_ns = min(times)  # type: ignore[type-var]
        repeated, answers.repeated = answers.repeated, False
        if time_ns == self._answered and not repeated:
            return
        if all(answers.done(name, time_ns) for name in answers.members):
            self._answered = time_ns
            self.answer(time_ns)

    def close(self) -> None:
        super().close()
        if self._followers is not None:
            self._followers.close()


class Leader:
    """The sim's side: its token, the members and their answers, and whether a tick may go."""

    def __init__(self, host: Host, world: str, log: Any) -> None:
        LEDGER.enabled = True
        self.host, self.log = host, log
        self._token = host.session.liveliness().declare_token(f"{LEADER}/{keys.mangle(world)}")
        self.joined = False  # a member came since the clock was last published
        self._known: set[str] = set()
        self.answers = _Answers(host, "**", self._on_change)
        self._lagging: set[str] = set()
        self._waiting_since: float | None = None

    def _on_change(self) -> None:
        members = set(self.answers.members)
        for name in sorted(members ^ self._known):
            what = "a node on sim time" if name.startswith(NODE) else "a bridge"
            self.log.info(f"lockstep: {_node(name)} ({what}) "
                          f"{'joined' if name in members else 'left'}")
            self.joined = self.joined or name in members
        self._known = members

    @property
    def followers(self) -> list[str]:
        return [name for name, role in self.answers.members.items() if role == NODE]

    def ready(self, time_ns: int) -> bool:
        """Whether the tick after `time_ns` may be stepped: a follower is there, and every
        member has answered for it (or is no longer waited for)."""
        if not self.followers:
            self._waiting_since = None
            return False
        late = []
        for name in self.answers.members:
            if self.answers.done(name, time_ns):
                self._lagging.discard(name)
            elif name not in self._lagging:
                late.append(name)
        if not late:
            self._waiting_since = None
            return True
        now = time.monotonic()
        if self._waiting_since is None:
            self._waiting_since = now
        elif now - self._waiting_since > PATIENCE:
            for name in late:
                self.log.warning(f"lockstep: {_node(name)} did not answer for sim time "
                                 f"{time_ns / 1e9:.3f} s within {PATIENCE:g} s of wall time; "
                                 "going on without it until it answers")
                self._lagging.add(name)
            self._waiting_since = None
            return True
        return False

    def close(self) -> None:
        self.answers.close()
        self._token.undeclare()


def _node(member: str) -> str:
    """The node's name in a member's name."""
    return keys.unmangle(member.rsplit("/", 1)[-1])

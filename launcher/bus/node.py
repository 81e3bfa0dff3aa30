"""The node: names, parameters, its entities (made here, each handed the node's Host) and the
executor that runs their callbacks.

Threading: Zenoh delivers samples and queries on its own threads; they only put work on the
node's queue. `spin()` / `spin_once()` run every callback (subscriptions, services, timers)
one at a time on the calling thread, like rclpy's single-threaded executor, so a slow
callback delays other callbacks but never the bus. Publishing and calling services are safe
from any thread.

Names follow ROS 2 (relative, absolute, `~`), with the `--ros-args` remaps applied. Messages
are CDR (rosbags); keys, liveliness tokens and attachments follow rmw_zenoh (see keys.py).
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

import zenoh

from launcher.bus import components, keys, names, ros_args
from launcher.bus.clock import Clock
from launcher.bus.host import Host, direct, join_callback_threads
from launcher.bus.logging import Logger
from launcher.bus.node_parameters import NodeParameters
from launcher.bus.publisher import Publisher
from launcher.bus.qos import QoS, qos_of
from launcher.bus.services import Client, Service
from launcher.bus.session import before_threads_join, open_session
from launcher.bus.subscription import Subscription
from launcher.bus.timer import Rate, Timer
from launcher.errors import LaunchError

__all__ = ["Logger", "Node", "Parameter", "Publisher", "Rate", "Subscription", "Timer"]


def _hear_ctrl_c() -> None:
    """A node stops on SIGINT however it was started: a program started in the background
    of a script (`python node.py &`) inherits SIGINT ignored, and would then ignore Ctrl-C and
    the stop a launch sends. rclpy's init installs its handler over that as well."""
    if threading.current_thread() is threading.main_thread() and \
            signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


@contextlib.contextmanager
def _signals_held(forgive: bool) -> Iterator[None]:
    """SIGINT and SIGTERM wait until the block is done (on the main thread, where Python runs
    its handlers), then act as they would have: a node's teardown cut short by one would leave
    its Zenoh threads running, which the interpreter then joins for ever. `timeout -s INT`
    sends its signal twice (to the program and to its group), and the second can land in the
    teardown the first began. `forgive`: the node already stopped on a signal; one more asks
    for what is under way, and is dropped."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught: list[int] = []
    held = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
    held = {sig: handler for sig, handler in held.items() if handler is not None}
    for sig in held:  # (None: a handler not installed from Python, left alone)
        signal.signal(sig, lambda signum, _frame: caught.append(signum))
    try:
        yield
    finally:
        for sig, handler in held.items():
            signal.signal(sig, handler)
        if caught and not forgive:
            signal.raise_signal(caught[0])


# Registered before any node's destroy_node: the threading module runs its exit hooks in the
# reverse order, so this one after every node is destroyed.
before_threads_join(join_callback_threads)


class Parameter:
    def __init__(self, name: str, value: Any) -> None:
        self.name, self.value = name, value

RECHECK = 0.5  # s: how often a node looks again at the subscribers it watches (wall clock)


class Node:
    def __init__(self, name: str, *, namespace: str = "", argv: list[str] | None = None,
                 session: zenoh.Session | None = None, parameter_services: bool = True,
                 space: keys.Space = keys.ROS,
                 sim_time: Callable[[], float] | None = None) -> None:
        """`space` keys.SIM makes a node of the simulator's own side (the sim, the `gz`
        tools): off the ROS graph; an entity may still say where it goes (`space=`).
        `sim_time`: a node inside the sim reads sim time from the sim itself (seconds), not
        from /clock, when use_sim_time is true."""
        within = components.current()  # made by a component container: its arguments
        if within is not None:
            argv, session = within.argv, within.session
        self._owns_session = session is None
        parsed = ros_args.parse(sys.argv[1:] if argv is None else argv)
        self.name = names.check_node_name(parsed.node_name or name)
        self.namespace = names.check_namespace(parsed.namespace or namespace)
        self.remaps = parsed.remaps
        self.args = parsed.user_args
        logger = Logger(self.fully_qualified_name, parsed.log_level or "INFO")
        given = ros_args.node_parameters(parsed, self.name, self.namespace)
        if within is not None:
            given.update(within.parameters)
            within.nodes.append(self)
        self.params = NodeParameters(given, self.fully_qualified_name)
        self.owner: Any = None  # the rclpy node wrapping this one, if any
        self.host = Host(session or open_session(holds_nodes=True), self.namespace,
                         self.name, logger, space)
        self.session = self.host.session
        self._timers: list[Timer] = []
        self._watched: list[Any] = []  # publishers whose subscribers it watches (recheck)
        self._rechecks: Any = None  # the timer that looks again
        self._token = self.host.announce(keys.NODE)
        self._shutdown = self.session.declare_queryable(
            keys.shutdown_key(keys.domain(), str(self.session.zid()), self.host.node_id),
            direct(self._asked_to_shut_down)) if space == keys.ROS and within is None else None
        self._stopped = threading.Event()
        self.interrupted = False  # Ctrl-C arrived during spin()
        self._destroyed = False
        # (a node never destroyed would hang its program: see before_threads_join)
        before_threads_join(self.destroy_node)
        _hear_ctrl_c()
        if parameter_services:
            from launcher.bus.parameters import serve  # rcl_interfaces types: only here

            serve(self)
        self._clock = Clock(self, bool(self.params.values.get("use_sim_time", False)),
                            sim_time)

    def _asked_to_shut_down(self, query: Any) -> None:
        """`rosnode kill`: the process ends as on Ctrl-C (rospy's and rclpy's shutdown, the
        launch's supervision), once the asker has its answer."""
        query.reply(query.key_expr, b"killed")
        os.kill(os.getpid(), signal.SIGINT)

    # --- names ------------------------------------------------------------------------------
    @property
    def fully_qualified_name(self) -> str:
        return f"{self.namespace}/{self.name}"

    def resolve(self, name: str, what: str = "topic name",
                space: keys.Space | None = None) -> str:
        """The full name; remaps apply on the ROS graph only (a bridge's `-r` renames its
        ROS side, never the simulator's topic it reads, as ros_gz's does)."""
        full = names.expand(name, self.name, self.namespace, what)
        if (space or self.host.space) != keys.ROS:
            return full
        return names.remap(full, self.remaps, self.name, self.namespace)

    # --- endpoints --------------------------------------------------------------------------
    def create_publisher(self, type_name: str, topic: str, qos: QoS | int = 10,
                         space: keys.Space | None = None) -> Publisher:
        return self.host.adopt(Publisher(self.host, type_name, self.resolve(topic, space=space),
                                         qos_of(qos), space))

    def create_subscription(self, type_name: str, topic: str, callback: Callable[[Any], None],
                            qos: QoS | int = 10, raw: bool = False,
                            inline: bool = False, remote_only: bool = False,
                            space: keys.Space | None = None,
                            make: Callable[[str, list[Any]], Any] | None = None) -> Subscription:
        """`raw=True` hands the callback the CDR bytes instead of a message. `inline=True`
        runs the callback on Zenoh's delivery thread instead of the executor: no hand-over
        between threads (it halves the CPU of a 1 kHz stream), but the callback must be
        thread-safe against the node's other callbacks and must not block. `remote_only=True`
        ignores what this node publishes (a two-way bridge must not hear itself). `make`
        builds messages of other classes from field values (see TypeRegistry.deserialize)."""
        return self.host.adopt(Subscription(self.host, type_name,
                                            self.resolve(topic, space=space), callback,
                                            qos_of(qos), raw, inline, remote_only, space, make))

    def create_service(self, type_name: str, name: str,
                       callback: Callable[[Any, Any], Any],
                       space: keys.Space | None = None,
                       make: Callable[[str, list[Any]], Any] | None = None,
                       new_response: Callable[[], Any] | None = None,
                       type_hash: str | None = None) -> Service:
        return self.host.adopt(Service(self.host, type_name,
                                       self.resolve(name, "service name", space), callback,
                                       space, make, new_response, type_hash))

    def create_client(self, type_name: str, name: str,
                      space: keys.Space | None = None,
                      make: Callable[[str, list[Any]], Any] | None = None) -> Client:
        return self.host.adopt(Client(self.host, type_name,
                                      self.resolve(name, "service name", space), space, make))

    def spin_with(self, other: Node) -> None:
        """This node's callbacks run when `other` spins (one thread for both); call it before
        anything arrives."""
        self.host.share_queue(other.host)

    def watch_subscribers(self, publisher: Any, callback: Callable[[bool], None]) -> None:
        """`publisher.watch_subscribers(callback)`, and a look at what Zenoh says now every
        RECHECK seconds: a word of Zenoh's that never came, or came out of order, heals
        there (a lazy node left believing nobody listens never publishes again)."""
        publisher.watch_subscribers(callback)
        if self._rechecks is None:
            self._rechecks = self.create_timer(RECHECK, self._recheck)
        self._watched.append(publisher)

    def _recheck(self) -> None:
        self._watched = [publisher for publisher in self._watched if publisher.recheck()]

    def create_timer(self, period: float, callback: Callable[[], None],
                     clock: Clock | None = None) -> Timer:
        """Call `callback` every `period` seconds of the monotonic clock, or of `clock` (the
        node's `get_clock()`: sim time when use_sim_time is true, as rclpy's timers are)."""
        if period <= 0:
            raise LaunchError(f"timer period must be > 0, got {period}")
        timer = Timer(period, callback, clock)
        self._timers.append(timer)
        return timer

    def message(self, type_name: str, **fields: Any) -> Any:
        """A message of `type_name`; nested fields default to their zero values."""
        from launcher.bus.messages import build

        return build(type_name, fields)

    # --- parameters (bus/node_parameters.py: `params`) -----------------------------------
    def declare_parameter(self, name: str, default: Any = None) -> Parameter:
        return Parameter(name, self.params.default(name, default))

    def get_parameter(self, name: str) -> Parameter:
        return Parameter(name, self.params.get(name))

    def has_parameter(self, name: str) -> bool:
        return self.params.has(name)

    def set_parameters(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            self.params.set(parameter.name, parameter.value)

    def add_on_set_parameters_callback(self, callback: Callable[[str, Any], None]) -> None:
        self.params.on_set(callback)

    @property
    def parameters(self) -> dict[str, Any]:
        return self.params.values

    def get_logger(self) -> Logger:
        return self.host.logger

    def get_clock(self) -> Clock:
        return self._clock

    # --- executing --------------------------------------------------------------------------
    def spin_once(self, timeout: float | None = None) -> bool:
        """Run one ready callback (or due timer), waiting up to `timeout`; True if one ran."""
        wait = timeout
        ready = []
        for timer in self._timers:
            if timer.cancelled:
                continue
            until = timer.wait()
            if until == 0.0:
                ready.append(timer)
            elif until is not None:
                wait = until if wait is None else min(wait, until)
        if ready:
            min(ready, key=lambda t: t.next).fire()
            return True
        work = self.host.next_work(0)
        if work is None:  # idle: all that was due has run
            self._clock.caught_up()
            work = self.host.next_work(wait)
        if work is None:
            return False
        callback, args = work
        callback(*args)
        return True

    def spin(self, duration: float | None = None) -> None:
        """Run callbacks until Ctrl-C, `shutdown()`, or `duration` seconds.

        Ctrl-C ends the spin quietly (so `node.spin(); node.destroy_node()` is a whole
        program) and sets `interrupted`, for loops that spin in slices."""
        end = None if duration is None else time.monotonic() + duration
        try:
            while not self._stopped.is_set():
                remaining = None if end is None else end - time.monotonic()
                if remaining is not None and remaining <= 0:
                    return
                self.spin_once(0.1 if remaining is None else min(0.1, remaining))
        except KeyboardInterrupt:
            self.interrupted = True

    def shutdown(self) -> None:
        self._stopped.set()

    @property
    def is_shutdown(self) -> bool:
        """shutdown() was called: spin() returns (a one-shot component says it is done)."""
        return self._stopped.is_set()

    def graph_session(self) -> zenoh.Session:
        """The session to ask who is on the bus (see Host.graph_session)."""
        return self.host.graph_session()

    def destroy_node(self) -> None:
        """Undeclare everything and close the session; safe to call more than once."""
        if self._destroyed:
            return
        self._destroyed = True
        with _signals_held(forgive=self.interrupted):
            self.host.close_graph_session()
            for entity in list(self.host.entities):
                # the session must close whatever happened to one entity
                with contextlib.suppress(zenoh.ZError, RuntimeError):
                    entity.destroy()
            self._token.undeclare()
            if self._shutdown is not None:
                with contextlib.suppress(zenoh.ZError):
                    self._shutdown.undeclare()
            if self._owns_session:
                self.session.close()


"""The web viewer's parts (launcher/sim/viewer.py, viewer_page.py, studio.py) with real MuJoCo
and Studio's own message classes; Studio's viewer thread is replaced by a recording handle."""

from __future__ import annotations

import logging
from types import SimpleNamespace

import mujoco
import pytest
from mujoco.studio import messages, plugin_registry, sim

from launcher.sim import studio, viewer_page
from launcher.sim.viewer import WebView

BOX = "<mujoco><worldbody><body><freejoint/><geom size='.1 .1 .1' type='box'/></body>" \
      "</worldbody></mujoco>"


def test_the_pages_controls_become_actions_and_all_else_it_sends_is_dropped():
    actions: list[str] = []
    reached: list[object] = []

    class Behind:  # what Studio's own handle would do with the rest (it must not see them)
        @messages.handler(priority=messages.Priority.INTERNAL)
        def _any(self, message: messages.Message) -> None:
            reached.append(message)

    registry = plugin_registry.PluginRegistry([viewer_page.Controls(actions.append), Behind()])
    registry.dispatch(messages.RequestPauseEvent(pause_state=sim.PauseState.NORMAL_PAUSED))
    registry.dispatch(messages.RequestPauseEvent(pause_state=sim.PauseState.UNPAUSED))
    registry.dispatch(messages.SingleStepEvent())
    registry.dispatch(messages.ResetEvent())
    assert actions == ["pause", "run", "step", "reset"]
    model = mujoco.MjModel.from_xml_string(BOX)
    data = mujoco.MjData(model)
    for sent in (messages.LoadModelEvent(path="/tmp/dropped.xml"),
                 messages.StateEvent.from_data(model, data, int(mujoco.mjtState.mjSTATE_QPOS)),
                 messages.MjOptionSnapshot(opt=model.opt),
                 messages.ThreadPoolEvent(nthread=64),
                 messages.StepControlSnapshot(pause_state=sim.PauseState.UNPAUSED)):
        registry.dispatch(sent)
    assert reached == []
    # the sim's own events go on to Studio's handle as before
    registry.dispatch(messages.StepEvent(model=model, data=data))
    assert len(reached) == 1


def test_browsers_are_counted_from_the_servers_log():
    browsers = studio.Browsers()
    logger = logging.getLogger("test-web-server")
    logger.addFilter(browsers)
    logger.propagate = False
    logger.setLevel(logging.INFO)
    logger.info("[StateWS] Browser connected (%d total)", 1)
    assert browsers.count == 1 and browsers.came.is_set()
    logger.info("[StateWS] Browser connected (%d total)", 2)
    logger.info("[StateWS] Browser disconnected (%d total)", 1)
    assert browsers.count == 1
    logger.info("[Session] Control granted to %s", "abc")  # (other lines leave it be)
    logger.info("[StateWS] Browser disconnected (%d total)", 0)
    assert browsers.count == 0 and not browsers.came.is_set()


class Handle:
    """Studio's ViewerHandle, recording."""

    def __init__(self) -> None:
        self.models: list[object] = []
        self.syncs = 0
        self.sent: list[object] = []

    def set_model(self, model, data) -> None:
        self.models.append(model)

    def sync(self, model, data) -> None:
        self.syncs += 1

    def send_to_viewer(self, message) -> None:
        self.sent.append(message)


def a_view(watched: bool) -> tuple[WebView, Handle]:
    view = WebView(8080, "127.0.0.1", 30)
    handle = Handle()
    view._studio = studio.Studio(handle, SimpleNamespace(watched=lambda: watched))
    view._camera = mujoco.MjvCamera()
    return view, handle


def a_world(xml: str = BOX) -> SimpleNamespace:
    model = mujoco.MjModel.from_xml_string(xml)
    return SimpleNamespace(model=model, data=mujoco.MjData(model), entities={})


@pytest.fixture(autouse=True)
def no_framing(monkeypatch):
    monkeypatch.setattr("launcher.sim.snapshot.framing", lambda world, names=None: None)


def test_with_no_browser_only_a_new_model_is_sent():
    view, handle = a_view(watched=False)
    world = a_world()
    view.follow(world, paused=False, now=0.0)
    assert handle.models == [world.model]  # (the next browser gets it at once)
    for step in range(1, 30):
        view.follow(world, paused=False, now=step * 0.04)
    assert handle.syncs == 1  # the new model's, none after it
    world2 = a_world(BOX.replace(".1 .1 .1", ".2 .2 .2"))  # a spawn recompiled it
    view.follow(world2, paused=False, now=2.0)
    assert handle.models == [world.model, world2.model]


def test_a_watched_view_is_sent_the_state_at_its_rate_and_the_pause_once():
    view, handle = a_view(watched=True)
    world = a_world()
    for step in range(1000):  # 1 s of the sim's 1 kHz batches, at 30 Hz
        view.follow(world, paused=step >= 500, now=step * 0.001)
    assert 28 <= handle.syncs <= 31
    pauses = [m.pause_state for m in handle.sent if isinstance(m, messages.StepControlSnapshot)]
    assert pauses == [sim.PauseState.UNPAUSED, sim.PauseState.NORMAL_PAUSED]


def test_the_pages_actions_reach_the_sim_after_its_sync():
    view, handle = a_view(watched=True)
    done: list[tuple[str, int]] = []
    view.on_action = lambda action: done.append((action, handle.syncs))
    view._actions.append("pause")  # (as Controls appends what the page pressed)
    view.follow(a_world(), paused=False, now=0.0)
    assert done == [("pause", 1)] and view._actions == []


def test_the_panels_buttons_are_where_a_test_presses_them():
    x0, y0 = viewer_page.button_centre(0)
    x1, _ = viewer_page.button_centre(1)
    assert x1 - x0 == viewer_page.BUTTON[0] + viewer_page.GAP
    assert viewer_page.PANEL_AT[0] < x0 - viewer_page.BUTTON[0] / 2
    assert y0 == viewer_page.PANEL_AT[1] + viewer_page.PAD + viewer_page.BUTTON[1] / 2


CAMERA = "<mujoco><worldbody><camera name='overhead' pos='0 0 5'/><body name='bot'>" \
         "<freejoint/><geom size='.1 .1 .1' type='box'/></body></worldbody></mujoco>"


@pytest.mark.parametrize("asked, expected", [
    ({"camera": "overhead"}, ("FIXED", 0)),
    ({"track": "bot"}, ("TRACKING", 1)),
    ({"track": "not_yet_spawned"}, ("FREE", None)),
    ({"camera": "no_such_camera"}, ("FREE", None)),
    ({}, ("FREE", None)),
])
def test_the_view_on_a_new_model_is_the_camera_or_the_tracked_entity_or_the_free_view(
        asked, expected):
    view = WebView(8080, "127.0.0.1", 30, **asked)
    view._camera = camera = mujoco.MjvCamera()
    world = a_world(CAMERA)
    world.entities = {"bot": SimpleNamespace(body=1)}
    view._frame(world)
    kind, index = expected
    assert camera.type == getattr(mujoco.mjtCamera, f"mjCAMERA_{kind}")
    if kind == "FIXED":
        assert camera.fixedcamid == index
    if kind == "TRACKING":
        assert camera.trackbodyid == index

"""What the page can do: the sim's controls in MuJoCo Studio's page, and nothing else.

Imported by studio.py (whose PageViewer takes no model dropped onto the page and draws only
for a browser). Two parts, on Studio's two sides, through its plugin API:

- `Panel` (the viewer thread) draws the sim's controls in the page: Pause or Run, Step and
  Reset, and whether the sim runs; each button sends Studio's own event for it.
- `Controls` (the sim's side, in `ViewerHandle.sync`) takes those events as actions for the
  sim's control path (the one `/world/<w>/control` takes), and drops every other thing the page
  could send (a state it dragged, a model to load, physics options, keyframes): the page shows
  the world, it does not change it but through the sim's controls.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from mujoco.studio import messages, plugin, sim
from mujoco.studio.dear_imgui import dear_imgui as imgui

PAUSED = sim.PauseState.NORMAL_PAUSED
RUNNING = sim.PauseState.UNPAUSED
# The panel's place and buttons, in the page's pixels (fixed, so a test can press them)
PANEL_AT = (10.0, 10.0)
BUTTON = (64.0, 26.0)
GAP = 6.0
PAD = 8.0
BUTTONS = ("pause", "step", "reset")  # the first reads "Run" while the sim is paused


def button_centre(index: int) -> tuple[float, float]:
    """Where a button of the panel is on the page (its centre)."""
    x = PANEL_AT[0] + PAD + index * (BUTTON[0] + GAP) + BUTTON[0] / 2
    return x, PANEL_AT[1] + PAD + BUTTON[1] / 2


class Panel(plugin.ViewerPlugin):
    """The sim's controls, drawn in the page's top left corner."""

    paused = False

    @messages.handler
    def _on_sim_state(self, snapshot: messages.StepControlSnapshot) -> None:
        self.paused = snapshot.pause_state != RUNNING

    @messages.handler
    def _on_build_gui(self, _: messages.BuildGuiEvent) -> None:
        window = imgui.WindowFlags
        flags = 0
        for flag in (window.NoDecoration, window.NoMove, window.NoSavedSettings,
                     window.NoFocusOnAppearing, window.NoNav, window.NoDocking):
            flags |= int(flag)
        width = 2 * PAD + len(BUTTONS) * BUTTON[0] + (len(BUTTONS) - 1) * GAP
        imgui.SetNextWindowPos(imgui.Vec2(*PANEL_AT))
        imgui.SetNextWindowSize(imgui.Vec2(width, 2 * PAD + BUTTON[1] + 24))
        imgui.Begin("launcher sim", None, flags)
        events = {"pause": messages.RequestPauseEvent(
                      pause_state=RUNNING if self.paused else PAUSED),
                  "step": messages.SingleStepEvent(), "reset": messages.ResetEvent()}
        for index, name in enumerate(BUTTONS):
            imgui.SetCursorPos(imgui.Vec2(PAD + index * (BUTTON[0] + GAP), PAD))
            label = "Run" if name == "pause" and self.paused else name.capitalize()
            if imgui.Button(label, imgui.Vec2(*BUTTON)):
                self.viewer.send_to_sim(events[name])
        imgui.SetCursorPos(imgui.Vec2(PAD, PAD + BUTTON[1] + 4))
        data = self.viewer.data
        time_now = f"{data.time:.2f} s" if data is not None else ""
        imgui.Text(f"{'paused' if self.paused else 'running'}  {time_now}")
        imgui.End()


def _dropping(kind: type[messages.Message]) -> Callable[[Any, Any], bool]:
    """A handler that takes the page's messages of `kind` first, and lets them go no further
    (Studio reads the type a handler takes from its annotation)."""
    def drop(self: Any, _: Any) -> bool:
        return True

    drop.__annotations__ = {"_": kind, "return": bool}
    return messages.handler(drop, priority=messages.Priority.CRITICAL)


class Controls(plugin.SimPlugin):
    """The page's events, on the sim's side: the controls become actions, the rest goes."""

    def __init__(self, act: Callable[[str], None]) -> None:
        self._act = act  # called with "pause", "run", "step" or "reset"

    @messages.handler(priority=messages.Priority.CRITICAL)
    def _on_pause(self, event: messages.RequestPauseEvent) -> bool:
        self._act("run" if event.pause_state == RUNNING else "pause")
        return True

    @messages.handler(priority=messages.Priority.CRITICAL)
    def _on_step(self, _: messages.SingleStepEvent) -> bool:
        self._act("step")
        return True

    @messages.handler(priority=messages.Priority.CRITICAL)
    def _on_reset(self, _: messages.ResetEvent) -> bool:
        self._act("reset")
        return True

    # what else a page could send: none of it reaches the world
    _drop_load = _dropping(messages.LoadModelEvent)
    _drop_state = _dropping(messages.StateEvent)
    _drop_perturb = _dropping(messages.PerturbSnapshot)
    _drop_options = _dropping(messages.MjOptionSnapshot)
    _drop_keyframe = _dropping(messages.KeyframeEvent)
    _drop_threads = _dropping(messages.ThreadPoolEvent)
    _drop_step_control = _dropping(messages.StepControlSnapshot)

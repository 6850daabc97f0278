"""The browser's control panel: status, the conversation, a request box, the question's
choices as buttons, history commands, save, the selected asset, view toggles and the ego
camera's rendered frame. Widgets live on the server, so every tab shows the same panel."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
import viser
from drivetwin.orchestrator.serve.conversation import HISTORY_COMMANDS, Message
from drivetwin.orchestrator.serve.overlays import OVERLAYS

__all__ = ["ChatPanel", "PanelActions"]

OVERLAY_LABELS = {"lidar": "LIDAR points", "lane_ids": "Lane ids", "landmarks": "Landmark labels",
                  "storyboard": "Storyboard routes and triggers"}  # fmt: skip
# A blank frame until the ego camera is first rendered: 16:9, like the rendered frames.
PLACEHOLDER_FRAME = (90, 160)


@dataclass(frozen=True)
class PanelActions:
    """What the panel's widgets do, supplied by the app."""

    send: Callable[[str], None]
    choose: Callable[[int], None]
    command: Callable[[str, str], None]
    toggle: Callable[[str, bool], None]
    follow_ego: Callable[[bool], None]
    render_ego: Callable[[], None]
    clear_selection: Callable[[], None]


def _quoted(text: str) -> str:
    """Text shown line for line as a quote that wraps (plans and diffs hold brackets and underscores)."""
    return "\n".join(f"> {_escape(line.strip())}  " for line in text.splitlines() if line.strip())


def conversation_markdown(messages: list[Message]) -> str:
    """The conversation as markdown, oldest first."""
    if not messages:
        return "*Type a request below, e.g. “make it rain” or “add a traffic cone in front of the library”.*"
    lines = []
    for message in messages:
        if message.role == "you":
            lines.append(f"**you:** {_escape(message.text)}")
        else:
            lines.append(_quoted(message.text) or "> (done)")
    return "\n\n".join(lines)


def _escape(text: str) -> str:
    return "".join("\\" + c if c in "\\`*_{}[]<>()#+-.!|" else c for c in text)


class ChatPanel:
    """Builds the widgets once and updates their contents."""

    def __init__(self, gui: viser.GuiApi, actions: PanelActions, save_path: str) -> None:
        self.gui = gui
        self.actions = actions
        gui.configure_theme(control_width="large", show_logo=False)
        self.status = gui.add_markdown("starting…")
        with gui.add_folder("Chat"):
            self.conversation = gui.add_markdown(conversation_markdown([]))
            self.request = gui.add_text("Request", "", hint="what to change; 'this' means the selected asset")
            self.send_button = gui.add_button("Send", icon=viser.Icon.SEND)
            self.question_folder = gui.add_folder("Question", visible=False)
            self._choice_buttons: list[viser.GuiButtonHandle] = []
            self.history = gui.add_button_group("History", [c.capitalize() for c in HISTORY_COMMANDS])
            self.save_path = gui.add_text("Save to", save_path)
            self.save_button = gui.add_button("Save")
        with gui.add_folder("Selected asset"):
            self.selected = gui.add_markdown("*Click an asset in the view to select it.*")
            self.clear_button = gui.add_button("Clear selection")
        with gui.add_folder("View"):
            self.toggles = {name: gui.add_checkbox(OVERLAY_LABELS[name], False) for name in OVERLAYS}
            self.follow = gui.add_checkbox("Follow ego", False)
        with gui.add_folder("Ego camera"):
            self.render_button = gui.add_button("Render ego camera")
            blank = np.zeros((*PLACEHOLDER_FRAME, 3), dtype=np.uint8)
            self.rgb = gui.add_image(blank, label="RGB (hybrid renderer)", format="jpeg")
            self.depth = gui.add_image(blank, label="Depth", format="png")
        self._wire()

    def _wire(self) -> None:
        actions = self.actions

        @self.send_button.on_click
        def _(_: viser.GuiEvent[Any]) -> None:
            text = self.request.value
            if text.strip():
                self.request.value = ""  # type: ignore[misc]  # viser has the setter; its typing hides it
                actions.send(text)

        @self.history.on_click
        def _(event: viser.GuiEvent[viser.GuiButtonGroupHandle]) -> None:
            actions.command(event.target.value.lower(), "")

        @self.save_button.on_click
        def _(_: viser.GuiEvent[Any]) -> None:
            actions.command("save", self.save_path.value)

        @self.clear_button.on_click
        def _(_: viser.GuiEvent[Any]) -> None:
            actions.clear_selection()

        @self.render_button.on_click
        def _(_: viser.GuiEvent[Any]) -> None:
            actions.render_ego()

        @self.follow.on_update
        def _(_: viser.GuiEvent[Any]) -> None:
            actions.follow_ego(self.follow.value)

        for name, checkbox in self.toggles.items():
            checkbox.on_update(self._toggled(name, checkbox))

    def _toggled(self, name: str, checkbox: viser.GuiCheckboxHandle) -> Callable[[viser.GuiEvent[Any]], None]:
        return lambda _: self.actions.toggle(name, checkbox.value)

    def show_conversation(self, messages: list[Message], choices: list[str]) -> None:
        """Show the conversation and, while a question is open, one button per reading."""
        self.conversation.content = conversation_markdown(messages)
        for button in self._choice_buttons:
            button.remove()
        self._choice_buttons = []
        with self.question_folder:
            for number, text in enumerate(choices, start=1):
                button = self.gui.add_button(f"{number}. {text}")
                button.on_click(self._chosen(number))
                self._choice_buttons.append(button)
        self.question_folder.visible = bool(choices)

    def _chosen(self, number: int) -> Callable[[viser.GuiEvent[Any]], None]:
        return lambda _: self.actions.choose(number)

    def show_status(self, text: str) -> None:
        self.status.content = text

    def show_selected(self, text: str) -> None:
        self.selected.content = text

    def show_frame(self, rgb: npt.NDArray[np.uint8], depth: npt.NDArray[np.uint8]) -> None:
        self.rgb.image = rgb
        self.depth.image = depth

"""The browser view's app in-process: a real viser server, Session, LiveWorld and hybrid renderer."""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from drivetwin.orchestrator.live import LiveWorld
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.serve.app import ServeApp
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.defaults import load_world


@pytest.fixture
def app(tmp_path: Path) -> Iterator[ServeApp]:
    session = Session(load_world("campus"), make_planner("rules"), journal_path=tmp_path / "journal.jsonl")
    live = LiveWorld(session, simulate=True, background=False)
    app = ServeApp(session, live, port=0, frames_dir=tmp_path / "frames", update_hz=10)
    yield app
    app.close()
    live.close()
    session.close()


def test_a_clicked_asset_shows_its_properties_and_is_this_in_the_next_request(app: ServeApp) -> None:
    node = next(n for n, b in app.sync._batches.items() if "tree_4" in b.asset_ids)
    app.sync.on_asset_click(app.sync.asset_at(node, app.sync._batches[node].asset_ids.index("tree_4")))  # type: ignore[misc]
    assert "**tree_4** (tree)" in app.panel.selected.content
    before = app.session.scene.asset("tree_4")
    app._send("move this 3 m left")
    after = app.session.scene.asset("tree_4")
    assert before is not None and after is not None
    assert math.hypot(after.pose.x - before.pose.x, after.pose.y - before.pose.y) == pytest.approx(3.0)
    assert "tree\\_4 3 m left" in app.panel.conversation.content


def test_the_status_line_counts_the_assets_of_the_session(app: ServeApp) -> None:
    assert f"assets: {len(app.session.scene.assets)} (+ ego)" in app.status_text()
    app._send("add a traffic cone in front of the library")
    assert f"assets: {len(app.session.scene.assets)} (+ ego)" in app.panel.status.content
    assert app.sync.instance_count() == len(app.session.scene.assets) + 1


def test_a_question_shows_one_button_per_reading_and_a_choice_applies_it(app: ServeApp) -> None:
    from drivetwin.orchestrator.planning import Question, Reading
    from drivetwin.tools import ToolCall

    rain = Reading(text="rain", calls=[ToolCall(tool="set_weather", args={"kind": "rain", "intensity": 0.5})])
    snow = Reading(text="snow", calls=[ToolCall(tool="set_weather", args={"kind": "snow", "intensity": 0.5})])
    app.session.pending = ("make the weather bad", Question(text="which weather?", readings=[rain, snow]))
    app.conversation.question = app.session.pending[1]
    app._after_turn()
    assert [b.label for b in app.panel._choice_buttons] == ["1. rain", "2. snow"]
    app._choose(2)
    assert app.session.scene.environment.weather.kind == "snow"
    assert app.panel._choice_buttons == []


def test_the_ego_camera_frame_is_rendered_on_demand(app: ServeApp) -> None:
    app.render_ego()
    rgb, depth = app.panel.rgb.image, app.panel.depth.image
    assert rgb is not None and rgb.shape == (360, 640, 3) and rgb.reshape(-1, 3).var(axis=0).sum() > 100
    assert depth is not None and depth.shape == (360, 640, 3) and len(np.unique(depth)) > 10


def test_the_lidar_overlay_draws_a_scan_from_the_ego(app: ServeApp) -> None:
    app._toggle("lidar", True)
    assert app.overlays.counts["lidar"] > 100
    app._toggle("lidar", False)
    assert app.overlays.counts["lidar"] == 0


def test_an_update_rate_out_of_range_is_refused(app: ServeApp) -> None:
    with pytest.raises(ValueError, match="update rate 0 per second is out of range; give 0 < rate <= 120"):
        ServeApp(app.session, app.live, port=0, update_hz=0)

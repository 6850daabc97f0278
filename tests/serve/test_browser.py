"""`drivetwin serve` in a real headless Chromium: load, request, watch the scene change, undo, save.

The server is the real command in a subprocess on a free port of 127.0.0.1 (rule planner:
fast); the browser is Debian's chromium driven by its chromedriver through Selenium.
"""

from __future__ import annotations

import json
import os
import re
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

selenium = pytest.importorskip("selenium", reason="the dev extra installs selenium")
from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.remote.webdriver import WebDriver  # noqa: E402

DRIVETWIN = [sys.executable, "-c", "from drivetwin.orchestrator.cli import main; main()"]
CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--window-size=900,600"]  # fmt: skip
# Headless Chromium draws WebGL in software and redraws on every pose update: a few a second
# keep the page responsive on 2 busy cores (the world still moves, once a second; `bench serve`
# measures the server at 30 a second).
UPDATE_HZ = 1
STARTUP_S = 180.0  # the server imports MuJoCo, the planner and the renderer on 2 busy cores
WAIT_S = 90.0
PANEL_WIDTH_PX = 400  # the control panel on the right; the 3D view is the rest of the window
# A blank or single-colour page has a pixel variance near 0; the campus view is far above this.
MIN_VIEW_VARIANCE = 100.0

pytestmark = [
    pytest.mark.slow,  # about 90 s: Chromium draws WebGL in software; CI runs it (it installs chromium)
    pytest.mark.skipif(not (Path(CHROMIUM).exists() and Path(CHROMEDRIVER).exists()),
                       reason="needs Debian's chromium and chromium-driver (CI installs them)"),
]


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


class Served:
    """A running `drivetwin serve` subprocess and where it lives."""

    def __init__(self, workdir: Path) -> None:
        self.workdir = workdir
        self.port = _free_port()
        self.log = workdir / "serve.log"
        env = {**os.environ, "DRIVETWIN_STATE": str(workdir / "state"), "MUJOCO_GL": os.environ.get("MUJOCO_GL", "egl")}
        self.process = subprocess.Popen(
            [*DRIVETWIN, "serve", "--planner", "rules", "--world", "campus",
             "--port", str(self.port), "--journal", str(workdir / "journal.jsonl"), "--update-hz", str(UPDATE_HZ)],
            cwd=workdir, env=env, stdout=self.log.open("w"), stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        deadline = time.monotonic() + STARTUP_S
        while "drivetwin serve:" not in self.log.read_text():
            if self.process.poll() is not None or time.monotonic() > deadline:
                raise RuntimeError(f"drivetwin serve did not start:\n{self.log.read_text()}")
            time.sleep(0.5)
        self.url = re.search(r"http://\S+", self.log.read_text().split("drivetwin serve:")[1]).group(0)  # type: ignore[union-attr]

    def stop(self) -> int:
        self.process.send_signal(signal.SIGTERM)
        return self.process.wait(timeout=60)


@pytest.fixture(scope="module")
def served(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    served = Served(tmp_path_factory.mktemp("serve"))
    yield served
    if served.process.poll() is None:
        served.stop()


@pytest.fixture(scope="module")
def browser(tmp_path_factory: pytest.TempPathFactory) -> Iterator[WebDriver]:
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in [*CHROMIUM_FLAGS, f"--user-data-dir={tmp_path_factory.mktemp('chromium-profile')}"]:
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    yield driver
    driver.quit()


def _page_text(driver: WebDriver) -> str:
    return str(driver.find_element(By.TAG_NAME, "body").text)


def _wait_for(driver: WebDriver, pattern: str) -> re.Match[str]:
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        found = re.search(pattern, _page_text(driver))
        if found:
            return found
        time.sleep(0.5)
    raise AssertionError(f"the page never showed {pattern!r}; it shows:\n{_page_text(driver)[:2000]}")


def _shown_assets(driver: WebDriver) -> int:
    return int(_wait_for(driver, r"assets: (\d+) \(\+ ego\)").group(1))


def _input_labelled(driver: WebDriver, label: str) -> object:
    return driver.find_element(By.XPATH, f"//label[normalize-space()='{label}']/following::input[1]")


def _button(driver: WebDriver, text: str) -> object:
    return driver.find_element(By.XPATH, f"//button[normalize-space()='{text}']")


def _screenshot(driver: WebDriver, path: Path) -> np.ndarray:
    driver.save_screenshot(str(path))
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.float64)


def _save_scene(driver: WebDriver, served: Served, name: str) -> dict[str, object]:
    path_box = _input_labelled(driver, "Save to")
    path_box.clear()  # type: ignore[attr-defined]
    path_box.send_keys(name)  # type: ignore[attr-defined]
    time.sleep(0.5)  # the text box syncs its value to the server as it is typed
    _button(driver, "Save").click()  # type: ignore[attr-defined]
    _wait_for(driver, re.escape(f"saved {name}"))
    return json.loads((served.workdir / name).read_text())  # type: ignore[no-any-return]


def test_a_request_typed_in_the_browser_changes_the_world_and_undo_restores_it(
        served: Served, browser: WebDriver, tmp_path: Path) -> None:
    browser.get(served.url)
    start = _shown_assets(browser)
    time.sleep(3)  # let the software WebGL draw the first frames
    view = _screenshot(browser, tmp_path / "loaded.png")[:, :-PANEL_WIDTH_PX]
    assert view.reshape(-1, 3).var(axis=0).sum() > MIN_VIEW_VARIANCE, "the 3D view is blank"
    assert start == len(_save_scene(browser, served, "before.json")["assets"])  # type: ignore[arg-type]

    request = _input_labelled(browser, "Request")
    request.send_keys("add a traffic cone in front of the library")  # type: ignore[attr-defined]
    time.sleep(0.5)
    _button(browser, "Send").click()  # type: ignore[attr-defined]
    _wait_for(browser, rf"assets: {start + 1} \(\+ ego\)")
    _wait_for(browser, r"\+ traffic_cone_1")  # the diff, as chat prints it
    _screenshot(browser, tmp_path / "changed.png")
    saved = _save_scene(browser, served, "after.json")
    assert len(saved["assets"]) == start + 1  # type: ignore[arg-type]
    assert any(a["id"] == "traffic_cone_1" for a in saved["assets"])  # type: ignore[attr-defined,index]

    browser.find_element(By.XPATH, "//button[normalize-space()='Undo']").click()
    _wait_for(browser, rf"assets: {start} \(\+ ego\)")
    undone = _screenshot(browser, tmp_path / "undone.png")[:, :-PANEL_WIDTH_PX]
    assert undone.reshape(-1, 3).var(axis=0).sum() > MIN_VIEW_VARIANCE
    assert len(_save_scene(browser, served, "undone.json")["assets"]) == start  # type: ignore[arg-type]


def test_a_second_tab_watches_the_same_session(served: Served, browser: WebDriver) -> None:
    browser.get(served.url)
    first = _shown_assets(browser)
    browser.switch_to.new_window("tab")
    try:
        browser.get(served.url)
        assert _shown_assets(browser) == first
        _input_labelled(browser, "Request").send_keys("make it rain")  # type: ignore[attr-defined]
        time.sleep(0.5)
        _button(browser, "Send").click()  # type: ignore[attr-defined]
        _wait_for(browser, r"12:00, rain")
    finally:
        browser.close()
        browser.switch_to.window(browser.window_handles[0])
    _wait_for(browser, r"12:00, rain")  # the first tab sees the second tab's edit


def test_a_second_server_cannot_write_the_same_journal(served: Served) -> None:
    env = {**os.environ, "DRIVETWIN_STATE": str(served.workdir / "state")}
    second = subprocess.run(
        [*DRIVETWIN, "serve", "--planner", "rules", "--port", str(_free_port()),
         "--journal", str(served.workdir / "journal.jsonl"), "--no-sim"],
        cwd=served.workdir, env=env, capture_output=True, text=True, timeout=STARTUP_S, stdin=subprocess.DEVNULL)
    assert second.returncode == 1
    assert "Error:" in second.stderr and "journal" in second.stderr.lower()


def test_the_server_stops_cleanly_and_ends_its_journal(served: Served) -> None:
    assert served.stop() == 0
    last = json.loads((served.workdir / "journal.jsonl").read_text().splitlines()[-1])
    assert last["event"] == "end"

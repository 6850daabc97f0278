"""`drivetwin export SCENE.json --to OUT.xosc`: a scene as OpenSCENARIO, its roads as OpenDRIVE.

The same `export_scene` serves the REPL's `export PATH` command.
"""

from __future__ import annotations

from pathlib import Path

import click
from drivetwin.worlds.scene import Scene, SceneFileError

__all__ = ["ExportError", "export_command", "export_scene"]

EXPORT_SUFFIXES = (".xosc",)


class ExportError(ValueError):
    """An export target drivetwin does not write, or a written file that does not validate."""


def export_scene(scene: Scene, target: str | Path, validate: bool = True) -> list[Path]:
    """Write `scene` to `target` (.xosc, with a .xodr beside it), both validated; the files written."""
    from drivetwin.worlds.export.opendrive import OpenDriveError, validate_opendrive
    from drivetwin.worlds.export.openscenario import OpenScenarioError, export_openscenario, validate_openscenario

    path = Path(target)
    if path.suffix.lower() not in EXPORT_SUFFIXES:
        raise ExportError(
            f"cannot export to {path.name!r}: the target must end in {', '.join(EXPORT_SUFFIXES)} (OpenSCENARIO)")
    scenario, roads = export_openscenario(scene, path)
    if validate:
        try:
            validate_openscenario(scenario)
            validate_opendrive(roads)
        except (OpenScenarioError, OpenDriveError) as exc:
            raise ExportError(str(exc)) from exc
    return [scenario, roads]


@click.command(name="export")
@click.argument("scene_file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--to", "target", required=True, type=click.Path(dir_okay=False, path_type=Path),
              help="the OpenSCENARIO file to write (.xosc); the road network goes beside it as .xodr")
@click.option("--no-validate", is_flag=True, help="skip checking the file against the OpenSCENARIO XSD")
def export_command(scene_file: Path, target: Path, no_validate: bool) -> None:
    """Export a saved scene (its storyboard, actors, environment and roads) as OpenSCENARIO."""
    try:
        scene = Scene.load(scene_file)
        written = export_scene(scene, target, validate=not no_validate)
    except (SceneFileError, ExportError, OSError) as exc:
        raise click.ClickException(str(exc)) from exc
    events = sum(1 for _ in scene.storyboard.events())
    checked = "" if no_validate else ", valid against the OpenSCENARIO 1.2 XSD; roads valid OpenDRIVE 1.7"
    click.echo(f"wrote {written[0]} ({len(scene.all_assets())} entities, {events} events{checked}) and {written[1]}")

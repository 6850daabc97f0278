"""`drivetwin worlds import FILE --name NAME`: a road map becomes a world that loads by name."""

from __future__ import annotations

from pathlib import Path

import click

__all__ = ["import_command"]


@click.command("import")
@click.argument("map_file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--name", required=True, help="the world's name (lower-case letters, digits, '_' or '-')")
@click.option("--replace", is_flag=True, help="overwrite an imported world of the same name")
def import_command(map_file: Path, name: str, replace: bool) -> None:
    """Import an OpenDRIVE (.xodr) or OpenStreetMap (.osm) file as a world.

    The world goes to the user's data folder ($DRIVETWIN_DATA, else $XDG_DATA_HOME/drivetwin,
    else ~/.local/share/drivetwin) and then loads by name: drivetwin chat --world NAME.

    Example: drivetwin worlds import town.osm --name town
    """
    from drivetwin.worlds.opendrive.package import MapImportError, import_map

    try:
        report = import_map(map_file, name, replace=replace)
    except MapImportError as exc:
        raise click.ClickException(str(exc)) from exc
    click.echo(f"imported {report.kind} map {map_file.name} as world {report.name!r} in {report.seconds:.2f} s: "
               f"{report.lanes} lanes, {report.sidewalks} sidewalks, {report.crossings} crossings, "
               f"{report.junctions} junctions, {report.buildings} buildings, {report.landmarks} landmarks, "
               f"{report.props} signals and props ({report.folder})")

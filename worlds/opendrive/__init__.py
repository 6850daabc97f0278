"""Road-map worlds: OpenDRIVE files (read with pyxodr-omega-prime; reader.py says why) and
OpenStreetMap files (converted with SUMO's netconvert) become drivetwin Scenes.

Public entry points: `package.import_map`, `package.scene_from_file`, `package.user_world_folder`
and the `drivetwin worlds import` command (`cli.import_command`). Nothing is imported here, so
the CLI starts without loading the map libraries.
"""

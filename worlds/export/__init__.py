"""Writing drivetwin worlds in other tools' formats: OpenDRIVE road networks (opendrive.py),
OpenSCENARIO scenarios (openscenario.py; read back by openscenario_read.py)."""

"""Writing drivetwin worlds in other tools' formats: OpenDRIVE road networks (opendrive.py)."""

"""drivetwin."""

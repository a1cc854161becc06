"""lagrade's grader: parse student answers safely and judge them by their physics."""

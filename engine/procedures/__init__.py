"""One design worked through as named steps: the bolt as bought, the clutch as built, the
striker cycle."""

"""Actions and substitutions as small objects, and the registry frontends look tags up in."""

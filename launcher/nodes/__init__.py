"""Built-in executables: thin mains over bus/ and sim/."""

"""The event loop: launch context, events, process supervision (the OS reached through
system.py only), output, logs and the watchdog (reaper.py)."""

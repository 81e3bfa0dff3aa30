"""The MuJoCo world server (see server.py)."""

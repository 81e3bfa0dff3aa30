"""Where a point of the world is on the Earth: the world's `<spherical_coordinates>` (WGS84:
latitude, longitude and elevation of the world's origin, the heading of its x axis) and the
conversions from world coordinates to east-north-up and to latitude, longitude, altitude."""

from __future__ import annotations

import math
from dataclasses import dataclass

SEMI_MAJOR = 6378137.0  # WGS84, m
FLATTENING = 1 / 298.257223563
ECCENTRICITY2 = FLATTENING * (2 - FLATTENING)


@dataclass(frozen=True)
class SphericalCoordinates:
    """Where the world's origin is on the Earth (degrees, metres) and how its x axis points:
    `heading_deg` turns it from east, positive clockwise seen from above (Gazebo's)."""

    latitude_deg: float = 0.0
    longitude_deg: float = 0.0
    elevation: float = 0.0
    heading_deg: float = 0.0

    def enu(self, x: float, y: float, z: float) -> tuple[float, float, float]:
        """World coordinates as east, north, up."""
        heading = math.radians(self.heading_deg)
        return (x * math.cos(heading) + y * math.sin(heading),
                -x * math.sin(heading) + y * math.cos(heading), z)

    def geodetic(self, x: float, y: float, z: float) -> tuple[float, float, float]:
        """(latitude°, longitude°, altitude m) of a point given in world coordinates."""
        east, north, up = self.enu(x, y, z)
        lat, lon = math.radians(self.latitude_deg), math.radians(self.longitude_deg)
        origin = _ecef(lat, lon, self.elevation)
        sl, cl, so, co = math.sin(lat), math.cos(lat), math.sin(lon), math.cos(lon)
        point = (origin[0] - so * east - sl * co * north + cl * co * up,
                 origin[1] + co * east - sl * so * north + cl * so * up,
                 origin[2] + cl * north + sl * up)
        return _geodetic(*point)


def _ecef(lat: float, lon: float, height: float) -> tuple[float, float, float]:
    n = SEMI_MAJOR / math.sqrt(1 - ECCENTRICITY2 * math.sin(lat) ** 2)
    return ((n + height) * math.cos(lat) * math.cos(lon),
            (n + height) * math.cos(lat) * math.sin(lon),
            (n * (1 - ECCENTRICITY2) + height) * math.sin(lat))


def _geodetic(x: float, y: float, z: float) -> tuple[float, float, float]:
    """ECEF to latitude, longitude (degrees) and height (iterated to well below a mm)."""
    lon = math.atan2(y, x)
    p = math.hypot(x, y)
    lat = math.atan2(z, p * (1 - ECCENTRICITY2))
    height = 0.0
    for _ in range(6):
        n = SEMI_MAJOR / math.sqrt(1 - ECCENTRICITY2 * math.sin(lat) ** 2)
        height = p / math.cos(lat) - n if abs(math.cos(lat)) > 1e-12 else abs(z) - n * (
            1 - ECCENTRICITY2)
        lat = math.atan2(z, p * (1 - ECCENTRICITY2 * n / (n + height)))
    return math.degrees(lat), math.degrees(lon), height

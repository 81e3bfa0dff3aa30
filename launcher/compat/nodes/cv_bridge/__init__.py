"""cv_bridge: sensor_msgs Images to and from numpy arrays (what OpenCV calls images), as ROS's
cv_bridge does, with ROS's encodings (rgb8, bgr8, rgba8, bgra8, mono8, mono16, 8UC1…64FC4,
bayer_*, yuv422). An image comes back as a view on the message's bytes where the encoding
allows (no copy); a conversion between encodings copies. OpenCV (`opencv-python-headless`,
an optional extra) is needed only for compressed images and bayer demosaicing, and its
absence is said plainly when one is asked for."""

from __future__ import annotations

import sys
from typing import Any

import numpy as np

_DEPTHS = {"8U": np.uint8, "8S": np.int8, "16U": np.uint16, "16S": np.int16, "32S": np.int32,
           "32F": np.float32, "64F": np.float64}
_NAMED = {"rgb8": ("8U", 3), "bgr8": ("8U", 3), "rgba8": ("8U", 4), "bgra8": ("8U", 4),
          "mono8": ("8U", 1), "mono16": ("16U", 1), "rgb16": ("16U", 3),
          "bgr16": ("16U", 3), "rgba16": ("16U", 4), "bgra16": ("16U", 4),
          "yuv422": ("8U", 2), "yuv422_yuy2": ("8U", 2), "uyvy": ("8U", 2),
          **{f"bayer_{p}{b}": ("8U" if b == 8 else "16U", 1)
             for p in ("rggb", "bggr", "gbrg", "grbg") for b in (8, 16)}}
_COLOUR = {"rgb8": "RGB", "bgr8": "BGR", "rgba8": "RGBA", "bgra8": "BGRA", "mono8": "L",
           "mono16": "L", "rgb16": "RGB", "bgr16": "BGR", "rgba16": "RGBA", "bgra16": "BGRA"}


class CvBridgeError(TypeError):
    """What cv_bridge raises: an encoding it cannot read or turn into another."""


def _layout(encoding: str) -> tuple[Any, int]:
    """(numpy dtype, channels) of an encoding."""
    if encoding in _NAMED:
        depth, channels = _NAMED[encoding]
        return np.dtype(_DEPTHS[depth]), channels
    for depth, dtype in _DEPTHS.items():
        if encoding.startswith(depth + "C"):
            try:
                return np.dtype(dtype), int(encoding[len(depth) + 1:])
            except ValueError:
                break
    raise CvBridgeError(f"Unrecognized image encoding [{encoding}]: expected one of "
                        f"{', '.join(sorted(_NAMED))}, or 8UC1…64FC4")


def _opencv() -> Any:
    try:
        import cv2
    except ImportError:
        raise CvBridgeError("this conversion needs OpenCV, which is not installed: "
                            "pip install opencv-python-headless (launcher's optional extra "
                            "`vision`)") from None
    return cv2


class CvBridge:
    """Converts between sensor_msgs images and numpy arrays (OpenCV's images)."""

    def __init__(self) -> None:
        pass

    # --- Image ----------------------------------------------------------------------------------
    def imgmsg_to_cv2(self, img_msg: Any, desired_encoding: str = "passthrough") -> np.ndarray:
        """An Image's pixels as an array (height × width, × channels when more than one), in
        its own encoding (`passthrough`) or converted to `desired_encoding`; a view on the
        message's bytes when no conversion is needed."""
        dtype, channels = _layout(img_msg.encoding)
        dtype = dtype.newbyteorder(">" if img_msg.is_bigendian else "<")
        height, width, step = int(img_msg.height), int(img_msg.width), int(img_msg.step)
        row = width * channels * dtype.itemsize
        data = img_msg.data
        size = data.nbytes if isinstance(data, np.ndarray) else len(data)
        if height and step < row or size < step * (height - 1) + row:
            raise CvBridgeError(f"the image's data ({size} bytes) does not hold {height} rows "
                                f"of {width} {img_msg.encoding} pixels at step {step}")
        flat = np.frombuffer(data, dtype=np.uint8)
        image = np.lib.stride_tricks.as_strided(
            flat, shape=(height, row), strides=(step, 1), writeable=False) \
            if step != row else flat[:height * row].reshape(height, row)
        image = image.view(dtype).reshape((height, width, channels) if channels > 1
                                          else (height, width))
        if dtype.byteorder not in ("=", "|") and (dtype.byteorder == ">") != \
                (sys.byteorder == "big"):
            image = image.astype(dtype.newbyteorder("="))
        if desired_encoding in ("passthrough", img_msg.encoding):
            return image
        return self._convert(image, img_msg.encoding, desired_encoding)

    def cv2_to_imgmsg(self, cvim: np.ndarray, encoding: str = "passthrough",
                      header: Any = None) -> Any:
        """An Image of the array `cvim`: its encoding named, or made from its dtype and
        channels (`passthrough`: 8UC3, 32FC1, …); `header` set when given."""
        from sensor_msgs.msg import Image

        if not isinstance(cvim, np.ndarray):
            raise TypeError("Your input type is not a numpy array")
        channels = 1 if cvim.ndim == 2 else cvim.shape[2]
        if encoding == "passthrough":
            kind = {v: k for k, v in _DEPTHS.items()}.get(cvim.dtype.type)
            if kind is None:
                raise CvBridgeError(f"numpy dtype {cvim.dtype} has no image encoding")
            encoding = f"{kind}C{channels}"
        else:
            dtype, wanted = _layout(encoding)
            if dtype != cvim.dtype or wanted != channels:
                raise CvBridgeError(f"encoding specified as {encoding}, but image has "
                                    f"incompatible type {cvim.dtype} with {channels} "
                                    "channels")
        image = np.ascontiguousarray(cvim)
        message = Image(height=image.shape[0], width=image.shape[1], encoding=encoding,
                        is_bigendian=image.dtype.byteorder == ">" or
                        (image.dtype.byteorder == "=" and sys.byteorder == "big"),
                        step=image.shape[1] * channels * image.dtype.itemsize,
                        data=image.tobytes())
        if header is not None:
            message.header = header
        return message

    # --- CompressedImage --------------------------------------------------------------------
    def compressed_imgmsg_to_cv2(self, cmprs_img_msg: Any,
                                 desired_encoding: str = "passthrough") -> np.ndarray:
        """A CompressedImage decoded (OpenCV needed) to an array, converted to
        `desired_encoding` unless `passthrough`."""
        cv2 = _opencv()
        buffer = np.frombuffer(bytes(cmprs_img_msg.data), dtype=np.uint8)
        image = cv2.imdecode(buffer, cv2.IMREAD_UNCHANGED)
        if image is None:
            raise CvBridgeError(f"cannot decode the compressed image "
                                f"(format '{cmprs_img_msg.format}')")
        if desired_encoding == "passthrough":
            return image
        source = "bgr8" if image.ndim == 3 and image.shape[2] == 3 else \
            "bgra8" if image.ndim == 3 else "mono8" if image.dtype == np.uint8 else "mono16"
        return self._convert(image, source, desired_encoding)

    def cv2_to_compressed_imgmsg(self, cvim: np.ndarray, dst_format: str = "jpg") -> Any:
        """A CompressedImage of the array, encoded as `dst_format` (jpg, png; OpenCV
        needed)."""
        from sensor_msgs.msg import CompressedImage

        cv2 = _opencv()
        ok, encoded = cv2.imencode(f".{dst_format}", cvim)
        if not ok:
            raise CvBridgeError(f"cannot encode the image as {dst_format}")
        return CompressedImage(format=dst_format, data=encoded.tobytes())

    # --- between encodings -----------------------------------------------------------------
    def _convert(self, image: np.ndarray, source: str, target: str) -> np.ndarray:
        if source.startswith("bayer_"):
            cv2 = _opencv()
            # OpenCV names a Bayer pattern by its second row (as cv_bridge maps them)
            pattern = {"rggb": "BG", "bggr": "RG", "gbrg": "GR", "grbg": "GB"}[source[6:10]]
            code = getattr(cv2, f"COLOR_Bayer{pattern}2{'RGB' if 'rgb' in target else 'BGR'}")
            image, source = cv2.cvtColor(image, code), "rgb8" if "rgb" in target else "bgr8"
        if source not in _COLOUR or target not in _COLOUR:
            _layout(target)  # an unknown one is named
            raise CvBridgeError(f"cannot convert {source} to {target}")
        src, dst = _COLOUR[source], _COLOUR[target]
        out = image
        if src != dst:
            if src == "L":
                out = np.repeat(out[..., None], 3, axis=2)
                src = "RGB"
            if dst == "L":
                rgb = out[..., :3] if src.startswith("RGB") else out[..., 2::-1]
                out = (rgb.astype(np.float32) @ np.array([0.299, 0.587, 0.114],
                                                         np.float32)).round()
            else:
                order = [src.index(c) if c in src else None for c in dst]
                if None in order:  # alpha added
                    full = np.full(out.shape[:2] + (len(dst),), np.iinfo(out.dtype).max
                                   if out.dtype.kind in "ui" else 1.0, dtype=out.dtype)
                    for k, c in enumerate(dst):
                        if c in src:
                            full[..., k] = out[..., src.index(c)]
                    out = full
                else:
                    out = out[..., order]
        dtype, _ = _layout(target)
        if out.dtype != dtype:
            scale = (np.iinfo(dtype).max / np.iinfo(out.dtype).max) \
                if out.dtype.kind in "ui" and dtype.kind in "ui" else 1.0
            out = (out.astype(np.float64) * scale).round().astype(dtype)
        return np.ascontiguousarray(out)


def get_cv_types() -> list[str]:
    """The encodings cv_bridge names (rgb8, mono16, …)."""
    return sorted(_NAMED)

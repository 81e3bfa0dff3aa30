"""cv_bridge, as ROS's: images to numpy arrays (a view where the encoding allows) and back,
conversions between ROS's encodings, rows with padding, and what needs OpenCV said plainly
when it is not installed (a test environment without it: the import is made to fail)."""

from __future__ import annotations

import builtins

import numpy as np
import pytest

from launcher.compat import finder

finder.install()

from cv_bridge import CvBridge, CvBridgeError  # noqa: E402
from sensor_msgs.msg import CompressedImage, Image  # noqa: E402


def test_an_image_comes_back_as_a_view_and_converts_between_encodings():
    bridge = CvBridge()
    picture = np.arange(4 * 5 * 3, dtype=np.uint8).reshape(4, 5, 3)
    message = bridge.cv2_to_imgmsg(picture, "rgb8")
    assert (message.encoding, message.step, message.height, message.width) == ("rgb8", 15, 4, 5)
    back = bridge.imgmsg_to_cv2(message)
    assert np.array_equal(back, picture) and not back.flags.owndata  # a view, not a copy
    assert np.array_equal(bridge.imgmsg_to_cv2(message, "bgr8"), picture[..., ::-1])
    mono = bridge.imgmsg_to_cv2(message, "mono8")
    assert mono.shape == (4, 5) and mono[0, 0] == round(0.299 * 0 + 0.587 * 1 + 0.114 * 2)
    rgba = bridge.imgmsg_to_cv2(message, "rgba8")
    assert rgba.shape == (4, 5, 4) and (rgba[..., 3] == 255).all()
    depth = np.full((2, 3), 1.5, dtype=np.float32)
    as_message = bridge.cv2_to_imgmsg(depth)
    assert as_message.encoding == "32FC1"
    assert np.array_equal(bridge.imgmsg_to_cv2(as_message, "32FC1"), depth)
    sixteen = bridge.cv2_to_imgmsg(np.full((2, 2), 1000, dtype=np.uint16), "16UC1")
    assert bridge.imgmsg_to_cv2(sixteen).dtype == np.uint16


def test_rows_with_padding_and_bad_images():
    bridge = CvBridge()
    padded = Image(height=2, width=2, encoding="mono8", step=4,
                   data=bytes([1, 2, 0, 0, 3, 4, 0, 0]))
    assert bridge.imgmsg_to_cv2(padded).tolist() == [[1, 2], [3, 4]]
    with pytest.raises(CvBridgeError, match=r"Unrecognized image encoding \[rgb9\]"):
        bridge.imgmsg_to_cv2(Image(height=1, width=1, encoding="rgb9", step=3, data=b"abc"))
    with pytest.raises(CvBridgeError, match="does not hold 2 rows of 2 mono8 pixels"):
        bridge.imgmsg_to_cv2(Image(height=2, width=2, encoding="mono8", step=2, data=b"ab"))
    with pytest.raises(CvBridgeError, match="encoding specified as rgb8, but image has "
                                            "incompatible type float32"):
        bridge.cv2_to_imgmsg(np.zeros((2, 2, 3), np.float32), "rgb8")


def test_what_needs_opencv_says_so_when_it_is_not_there(monkeypatch):
    real = builtins.__import__

    def no_cv2(name, *args, **kwargs):
        if name == "cv2":
            raise ImportError("No module named 'cv2'")
        return real(name, *args, **kwargs)
    monkeypatch.setattr(builtins, "__import__", no_cv2)
    with pytest.raises(CvBridgeError, match="needs OpenCV, which is not installed: pip install "
                                            "opencv-python-headless"):
        CvBridge().compressed_imgmsg_to_cv2(CompressedImage(format="jpeg", data=b"\xff\xd8"))


def test_compressed_images_and_bayer_through_opencv():
    """(OpenCV is the set-up's `vision` extra)"""
    bridge = CvBridge()
    picture = np.zeros((48, 64, 3), np.uint8)
    picture[:, :32] = (0, 0, 255)  # red on the left, in OpenCV's BGR
    compressed = bridge.cv2_to_compressed_imgmsg(picture, "png")
    assert compressed.format == "png" and bytes(compressed.data)[:4] == b"\x89PNG"
    back = bridge.compressed_imgmsg_to_cv2(compressed)
    assert np.array_equal(back, picture)
    rgb = bridge.compressed_imgmsg_to_cv2(compressed, "rgb8")
    assert rgb[0, 0].tolist() == [255, 0, 0]
    jpeg = bridge.cv2_to_compressed_imgmsg(picture)
    assert jpeg.format == "jpg" and bridge.compressed_imgmsg_to_cv2(jpeg).shape == (48, 64, 3)
    bayer = np.zeros((8, 8), np.uint8)
    bayer[0::2, 0::2] = 200  # the red sites of an RGGB pattern: a red picture
    mosaic = Image(height=8, width=8, encoding="bayer_rggb8", step=8, data=bayer.tobytes())
    colour = bridge.imgmsg_to_cv2(mosaic, "rgb8")
    assert colour.shape == (8, 8, 3)
    assert colour[2:6, 2:6, 0].mean() > 150 > colour[2:6, 2:6, 2].mean()

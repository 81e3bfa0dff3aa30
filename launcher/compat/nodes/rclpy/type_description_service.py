"""rclpy.type_description_service: the names of the `~/get_type_description` service's
switch. launcher does not serve type descriptions (its type store has no
type_description_interfaces), so TypeDescriptionService is left out."""

from rclpy.validate_topic_name import TOPIC_SEPARATOR_STRING  # noqa: F401 - as rclpy's offers it

START_TYPE_DESCRIPTION_SERVICE_PARAM = "start_type_description_service"


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)

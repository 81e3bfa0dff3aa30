"""launch.frontend: markup launch files (launch_xml, launch_yaml) and the decorators that make
a user's class a tag or a substitution of them, mapped onto launcher's frontend and registry."""

from launch.frontend import type_utils
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action, expose_substitution
from launch.frontend.parser import InvalidFrontendLaunchFileError, Parser

__all__ = ["Entity", "InvalidFrontendLaunchFileError", "Parser", "expose_action",
           "expose_substitution", "type_utils"]

"""What launcher leaves out of the real packages' surface on purpose, each with its reason.

Keys are as surface_check.py names a difference: "module" for a whole module, "module:Name"
for a name. The docs page of what is left out (docs/_gen/reference_fidelity.py) is made from
this table, and test_surface.py holds it to the truth: each entry must still be missing (a
name that launcher gains leaves this list), and the whole stays within 2% of the surface.
"""

from __future__ import annotations

TYPESUPPORT = ("The compiled type support of rclpy's wheels (rosidl's C extension modules); "
               "launcher's message classes are Python, serialised by its own CDR codec.")

ROS1_MASTER = ("ROS 1's XML-RPC master and node servers: launcher's nodes meet on its Zenoh bus, "
               "and their parameters live on launcher's parameter server.")
ROS1_WIRE = ("ROS 1's wire protocols (TCPROS, its serialisation and per-connection statistics): "
             "launcher's messages and services travel on its Zenoh bus, serialised as CDR.")
# what rospy.impl.tcpros_service takes from tcpros_base, which tcpros_base defines
TCPROS_TRANSPORT = ("TCPROSTransport", "TCPROSTransportProtocol", "get_tcpros_server_address",
                    "recv_buff", "start_tcpros_server")
ROS1_ROSOUT = ("rospy's /rosout and /clock plumbing: launcher's type store has no "
               "rosgraph_msgs/Log, rospy prints its log, and the node's clock follows /clock.")
ROSTEST_ROSLAUNCH = ("rostest's roslaunch-based runner (a ROS 1 launch parent and master per test "
                     "file): launcher's rostest command runs .test files on its own graph.")
ACTIONLIB_TEST_MSGS = ("actionlib's own test messages (Test, TestRequest, TwoInts actions): "
                       "launcher's type store does not carry them.")

ROSLAUNCH_XMLRPC = ("roslaunch's XML-RPC launch servers, its remote children over SSH and its "
                    "process listing over XML-RPC: launcher's runtime supervises a launch's "
                    "processes itself, other hosts' through its SSH supervisor.")

PYTEST_ITEMS = ("Makes a test's items through pytest's private Class._genfunctions, which "
                "launcher calls in one place only: its own launch_pytest plugin's collection.")

LARK_GRAMMAR = ("launch's lark grammar file and the lark Transformer over its parse tree: "
                "launcher reads `$(…)` with its own hand-written parser, which has neither.")

NODE_EXTENSIONS = ("launch_ros's Node action extensions (plugins found through the "
                   "'launch_ros.node_action' entry points, which tracing tools add) are not run "
                   "by launcher's Node action.")
LOAD_REQUEST = ("Builds composition_interfaces' LoadNode request for launch_ros's rclpy client; "
                "launcher's composable node loads go through its own loader.")

TYPE_DESCRIPTIONS = ("rclpy's type description service and its C extension's internals: launcher's "
                     "type store has no type_description_interfaces, and rclpy's C core is none "
                     "of launcher's.")

MIGRATION_RULES = ("rosbag's message migration rules (rule files and the chains and scaffolds "
                   "made of them): launcher runs none, so a bag migrates only where its "
                   "types match launcher's.")

LEFT_OUT: dict[str, str] = {
    **dict.fromkeys(("launch_ros.actions.node:NodeActionExtension",
                     "launch_ros.actions.node:g_entry_points_impl",
                     "launch_ros.actions.node:get_extensions",
                     "launch_ros.actions.node:instantiate_extension"), NODE_EXTENSIONS),
    "launch_ros.actions.load_composable_nodes:get_composable_node_load_request": LOAD_REQUEST,
    "launch_pytest.plugin:generate_test_items": PYTEST_ITEMS,
    **{f"{package}.{package}_s__rosidl_typesupport_{kind}": TYPESUPPORT
       for package in ("lifecycle_msgs", "rcl_interfaces")
       for kind in ("c", "fastrtps_c", "introspection_c")},
    **dict.fromkeys(("rospy.impl.init", "rospy.msproxy",
                     "rospy.impl.registration:RegManager", "rospy:MasterProxy",
                     "rospy:get_master", "rospy.client:get_master", "rostest:get_master",
                     *(f"rospy.impl.masterslave:{name}" for name in (
                         "ROSHandler", "apivalidate", "is_publishers_list", "LOG_API",
                         "RegManager"))),
                    ROS1_MASTER),
    **dict.fromkeys(("rospy.impl.tcpros", "rospy.impl.tcpros_pubsub", "rospy.impl.statistics",
                     "rospy.topics:QueuedConnection", "rospy.topics:get_tcpros_handler",
                     "rospy.topics:SubscriberStatisticsLogger",
                     "rospy.msg", "rospy:AnyMsg", "rospy.topics:serialize_message",
                     *(f"rospy.impl.{module}:{name}" for module in ("tcpros_base",
                                                                     "tcpros_service")
                       for name in TCPROS_TRANSPORT),
                     *(f"rospy.impl.tcpros_base:{name}" for name in (
                         "TCPServer", "TCPROSServer", "init_tcpros_server",
                         "deserialize_messages", "serialize_message")),
                     *(f"rospy.impl.tcpros_service:{name}" for name in (
                         "ServiceImpl", "TCPService", "TCPROSServiceClient",
                         "service_connection_handler"))),
                    ROS1_WIRE),
    **dict.fromkeys(("rospy.impl.rosout", "rospy.impl.simtime"), ROS1_ROSOUT),
    **dict.fromkeys(("rostest.rostest_parent", "rostest.runner",
                     "rostest.rostest_main:ROSTestLaunchParent"), ROSTEST_ROSLAUNCH),
    "actionlib.msg": ACTIONLIB_TEST_MSGS,
    **dict.fromkeys(("roslaunch.child", "roslaunch.server", "roslaunch.remote",
                     "roslaunch.remoteprocess", "roslaunch.netapi"), ROSLAUNCH_XMLRPC),
    **dict.fromkeys(("rclpy.type_description_service:TypeDescriptionService",
                     "rclpy.node:TypeDescriptionService",
                     "rclpy.impl.implementation_singleton:package"), TYPE_DESCRIPTIONS),
    **dict.fromkeys(("launch.frontend.parse_substitution:ExtractSubstitution",
                     "launch.frontend.parse_substitution:get_grammar_path"), LARK_GRAMMAR),
    **dict.fromkeys(("rosbag.migration:MessageUpdateRule", "rosbag.migration:RuleChain",
                     "rosbag.migration:ScaffoldNode"), MIGRATION_RULES),
}

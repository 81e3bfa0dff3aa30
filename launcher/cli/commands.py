"""Every command and verb of the command line, in one table: launcher's commands (which
`ros2 VERB` runs too), ROS 1's tools, and the words that are other programs' (TOOLS: their
words passed on as typed). A verb's module is named after it (cli/verbs.py builds the parsers,
importing only the chosen verb's module)."""

from __future__ import annotations

from launcher.cli.ros1 import TOOLS as ROS1_TOOLS
from launcher.cli.verbs import Group, Tool, Verb


def verbs(package: str, helps: dict[str, str], **modules: str) -> dict[str, Verb | Group]:
    """`package`'s verbs, each in the module of its name (or the one `modules` gives)."""
    return {name: Verb(f"{package}.{modules.get(name, name.replace('-', '_'))}", text)
            for name, text in helps.items()}


LAUNCHER: dict[str, Verb | Group | Tool] = {
    "launch": Verb("launcher.cli.launch_command", "run a launch file"),
    "test": Verb("launcher.cli.test_command", "run a launch test (as launch_test does)"),
    "batch": Verb("launcher.cli.batch_command", "run launch tests and launch files over a "
                  "matrix of arguments and seeds, here or on a Ray cluster"),
    "ps": Verb("launcher.cli.ps_command", "list the processes of the running launches"),
    "stop": Verb("launcher.cli.process_command", "stop one process of a running launch"),
    "start": Verb("launcher.cli.process_command", "start a stopped process of a running launch"),
    "restart": Verb("launcher.cli.process_command", "restart one process of a running launch"),
    "logs": Verb("launcher.cli.logs_command", "print one process's output from a running "
                 "launch"),
    "pkg": Group("packages: list, find, create", verbs("launcher.cli.pkg", {
        "list": "every package, with where it is",
        "prefix": "the install prefix of a package",
        "share": "the share folder of a package (the package itself)",
        "xml": "the package.xml of a package",
        "executables": "the executables of one or every package",
        "create": "write a new package from templates",
    }), "Packages in the workspaces launcher can see."),
    "env": Verb("launcher.cli.env_command", "print the environment the workspace's hooks make"),
    "topic": Group("topics: list, echo, pub, hz, bw, delay, info, type, find",
                   verbs("launcher.cli.topic", {
                       "list": "the topics on the bus",
                       "type": "the type of a topic",
                       "find": "the topics of a type",
                       "echo": "print the messages on a topic",
                       "pub": "publish a message",
                       "hz": "the rate of one or more topics, printed every second",
                       "bw": "the bandwidth a topic uses, printed every second",
                       "delay": "how old a topic's messages are when they arrive (now - "
                                "header.stamp), printed every second",
                       "info": "type and endpoints of a topic",
                   })),
    "bag": Group("record and play rosbag2 bags: record, play, info, list",
                 verbs("launcher.cli.bag", {
                     "record": "record topics to a bag",
                     "info": "what a bag holds",
                     "play": "publish a bag's messages again",
                     "convert": "a ROS 1 bag (.bag) to a rosbag2 bag (MCAP), or back",
                     "list": "the storage formats (or converters, compressors) bags can use",
                 })),
    "service": Group("services: list, call, type, find, info, echo",
                     verbs("launcher.cli.service", {
                         "list": "the services on the bus",
                         "call": "call a service once",
                         "type": "the type of a service",
                         "find": "the services of a type",
                         "info": "a service's type, and how many serve and call it",
                         "echo": "a service's events (its servers and clients must have "
                                 "introspection on)",
                     })),
    "node": Group("nodes: list, info", verbs("launcher.cli.node", {
        "list": "the nodes on the bus",
        "info": "a node's publishers, subscriptions, services",
    })),
    "action": Group("actions: list, info, type, send_goal", verbs("launcher.cli.action", {
        "list": "the actions on the graph",
        "info": "an action's servers and clients",
        "type": "the type of an action",
        "send_goal": "send a goal and wait for its result",
    })),
    "lifecycle": Group("lifecycle nodes: nodes, list, get, set", verbs("launcher.cli.lifecycle", {
        "nodes": "the lifecycle nodes on the graph",
        "list": "the transitions a node offers now",
        "get": "a node's state",
        "set": "take a transition",
    })),
    "control": Group("ros2_control's controller manager: list_controllers, load_controller, "
                     "switch_controllers, …", verbs("launcher.cli.control", {
                         "list_controllers": "the loaded controllers, their type and state",
                         "list_controller_types": "the controller types the manager can load",
                         "list_hardware_interfaces": "the command and state interfaces",
                         "list_hardware_components": "the hardware components",
                         "load_controller": "load a controller",
                         "set_controller_state": "configure, activate, deactivate or clean up",
                         "switch_controllers": "activate and deactivate in one step",
                         "unload_controller": "unload a controller",
                         "cleanup_controller": "clean up a controller",
                         "set_hardware_component_state": "a hardware component's state",
                         "reload_controller_libraries": "reload the controller libraries",
                         "view_controller_chains": "draw the controllers and their interfaces "
                                                   "(graphviz)",
                     })),
    "logger": Group("a node's logger levels: get, set", verbs("launcher.cli.logger", {
        "get": "a logger's level",
        "set": "set a logger's level",
    })),
    "graph": Verb("launcher.cli.graph_command", "draw the graph's nodes and topics (as rqt_graph)"),
    "plot": Verb("launcher.cli.plot_command", "draw fields of messages over time (as rqt_plot)"),
    "rviz2-layout": Verb("launcher.cli.rviz_command", "convert an rviz config into a Foxglove "
                                                      "layout"),
    "param": Group("parameters of a running node: list, get, set, describe, delete, dump, load",
                   verbs("launcher.cli.param", {
                       "list": "a node's parameter names",
                       "get": "one parameter's value",
                       "set": "set one parameter (the value is read as YAML)",
                       "describe": "parameters' types, descriptions and constraints",
                       "delete": "delete parameters (a node refuses it for one declared with a "
                                 "fixed type)",
                       "dump": "all of a node's parameters, as a params file",
                       "load": "set a node's parameters from a params file",
                   })),
    "rosparam": Group("ROS 1's rosparam: the graph's parameter server (list, get, set, delete, "
                      "dump, load)", verbs("launcher.cli.rosparam", {
                          "list": "the parameter names (below a namespace)",
                          "get": "a parameter's value, or a namespace's as YAML",
                          "set": "set a parameter (the value is read as YAML)",
                          "delete": "delete a parameter and everything below it",
                          "dump": "a namespace as YAML, to a file (or stdout)",
                          "load": "set the parameters of a YAML file (into a namespace)",
                      })),
    "interface": Group("message and service types: list, show, proto, package, packages",
                       verbs("launcher.cli.interface", {
                           "list": "every message and service type",
                           "show": "a type's definition (nested types indented)",
                           "proto": "a message's fields with their defaults, as YAML",
                           "package": "the types of one package",
                           "packages": "the packages that have types",
                       })),
    "run": Tool("launcher.cli.run_command", "run an executable of a package (as ros2 run / "
                                            "rosrun)", name="run", debug="lead"),
    "router": Verb("launcher.cli.router_command", "run a standing router of the graph (other "
                                                  "hosts join with --listen)"),
    "remote-supervisor": Verb("launcher.cli.remote_supervisor_command",
                              "(internal) what a launch runs on another host over ssh"),
    "sim": Tool("launcher.cli.sim_command", "run the MuJoCo world server", name="sim",
                debug="none"),
    "gz": Tool("launcher.cli.gz_command", "Gazebo's commands (sim, topic, service, model) over "
                                          "launcher's sim", strip=True),
    "doctor": Verb("launcher.cli.doctor_command", "check the install and the workspace; say what "
                                                  "to fix"),
}


def _types_tool(tool: str, kind: str, noun: str) -> Group:
    """rosmsg and rossrv: the same verbs over messages or services (`args.kind`)."""
    return Group(f"{tool} is a command-line tool for displaying information about ROS {noun} "
                 "types.", verbs("launcher.cli.ros1.rosmsg", {
                     "show": f"show {kind} description",
                     "list": f"list all {kind}s",
                     "package": f"list {kind}s in a package",
                 }), metavar="COMMAND", defaults={"kind": kind})


ROS1: dict[str, Group] = {  # ROS 1's tools that have verbs (the others: cli/ros1/TOOLS)
    "rostopic": Group("rostopic is a command-line tool for printing information about ROS "
                      "Topics.", verbs("launcher.cli.ros1.rostopic", {
                          "list": "list active topics",
                          "echo": "print messages to screen",
                          "pub": "publish data to topic",
                          "hz": "display publishing rate of topic",
                          "bw": "display bandwidth used by topic",
                          "info": "print information about active topic",
                          "type": "print topic or field type",
                      }), metavar="COMMAND"),
    "rosservice": Group("rosservice is a command-line tool for printing information about ROS "
                        "Services.", verbs("launcher.cli.ros1.rosservice", {
                            "list": "list active services",
                            "call": "call the service with the provided args",
                            "type": "print service type",
                            "info": "print information about service",
                        }), metavar="COMMAND"),
    "rosnode": Group("rosnode is a command-line tool for printing information about ROS "
                     "Nodes.", verbs("launcher.cli.ros1.rosnode", {
                         "list": "list active nodes",
                         "info": "print information about node",
                         "ping": "test connectivity to node",
                         "kill": "kill a running node",
                     }), metavar="COMMAND"),
    "rosmsg": _types_tool("rosmsg", "msg", "Message"),
    "rossrv": _types_tool("rossrv", "srv", "Service"),
    "rospack": Group("rospack is a command-line tool for retrieving information about ROS "
                     "packages.", verbs("launcher.cli.ros1.rospack", {
                         "find": "print the absolute path to the package",
                         "list": "print newline-separated list of <package-name> "
                                 "<package-dir> for all packages",
                         "list-names": "print newline-separated list of package names for "
                                       "all packages",
                         "depends1": "print the package's direct dependencies",
                     }, **{"list-names": "list"}), metavar="COMMAND"),
    "rosbag": Group("rosbag records and plays ROS 1 bags (.bag) on launcher's graph.",
                    verbs("launcher.cli.ros1.rosbag", {
                        "record": "record a bag file with the contents of specified topics",
                        "play": "play back the contents of one bag file",
                        "info": "summarize the contents of one bag file",
                    }), metavar="COMMAND"),
    "catkin": Group("catkin_tools' verbs for launcher's catkin workspaces",
                    verbs("launcher.cli.ros1.catkin", {
                        "build": "build the workspace's packages (catkin_make's work)",
                        "init": "mark the workspace",
                        "clean": "remove build/ and devel/",
                    }), strict=False),
}

# every word whose words after it are another program's, run by its tool (cli/main.py):
# launcher's commands of that kind (sim's flags, -h included; run's executable's), and
# ROS 2's `ros2` and colcon (compat/bin) and ROS 1's tools (cli/ros1), which `launcher -h`
# does not list
TOOLS: dict[str, Tool] = {
    **{word: entry for word, entry in LAUNCHER.items() if isinstance(entry, Tool)},
    "ros2": Tool("launcher.cli.ros2_command"),
    "colcon": Tool("launcher.cli.colcon_command"),
    **{word: Tool(module, strip=True) for word, module in ROS1_TOOLS.items()},
    **{word: Tool(group=group, strip=True) for word, group in ROS1.items()},
}

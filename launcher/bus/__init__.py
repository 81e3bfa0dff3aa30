"""The bus: Zenoh sessions, ROS 2 names and types (CDR), and the node API.

node.py makes the entities (publisher.py, subscription.py, services.py, timer.py), each handed
the node's Host (host.py); logging.py is the node's logger. keys.py holds rmw_zenoh's key and
token layout, types.py and messages.py the message types, wire.py the hand-packed CDR, graph.py
what is on the bus; session.py, router.py, discovery.py (finding and starting the graph's
router) and credentials.py connect to it.
"""

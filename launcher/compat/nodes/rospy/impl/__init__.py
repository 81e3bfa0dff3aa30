"""rospy.impl: the node's machinery behind rospy's API (in launcher, what its bus does not
already do: parameter validators, the parameter cache, registration listeners, rosout)."""

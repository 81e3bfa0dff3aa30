"""The kinds of fields in a type's definition, numbered as rosbags' Nodetype numbers them (its
definitions compare equal to these), without importing rosbags."""

BASE, NAME, ARRAY, SEQUENCE = 1, 2, 3, 4

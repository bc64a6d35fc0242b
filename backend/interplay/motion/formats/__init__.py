"""Capture file formats: BVH (read any hierarchy, write smpl22) and Acclaim ASF/AMC."""

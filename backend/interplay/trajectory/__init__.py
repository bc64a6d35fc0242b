"""The trajectory stage: make a motion's root follow a ground curve (drawn points or a preset shape). Entry: `trajectory.apply.apply_trajectory`."""

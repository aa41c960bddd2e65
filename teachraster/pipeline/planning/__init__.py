"""What a scene needs: the render plan's effects and their wording, and render's checked inputs.

The brief's third demand in code: every stage asks the plan whether its effect is needed,
and ``frame.plan`` says what ran, for how much, and why.
"""

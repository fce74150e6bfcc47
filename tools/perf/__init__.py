"""Speed against error: paired speed runs, Blender Cycles as a second renderer, where a render's time goes."""

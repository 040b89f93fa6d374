//! Scenes, cameras and lenses, and the exact references computed from analytic scenes.

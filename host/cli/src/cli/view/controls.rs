//! The camera controls: orbit about the target by dragging, zoom with the wheel, fly with
//! W/A/S/D (and Q/E down and up), and a click (press and release without moving) to focus.

use dof::scene::{Camera, Vec3};
use std::collections::HashSet;
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::keyboard::{KeyCode, PhysicalKey};

#[derive(Default)]
pub struct Controls {
    cursor: Option<(f64, f64)>,
    pressed_at: Option<(f64, f64)>,
    dragged: bool,
    held: HashSet<KeyCode>,
    /// A click to focus, in window pixels, waiting for the frame to handle it.
    pub focus_click: Option<(f64, f64)>,
    /// Keys pressed once (toggles), for the frame to handle.
    pub pressed: Vec<KeyCode>,
}

/// Radians of orbit per pixel dragged.
const ORBIT_PER_PIXEL: f32 = 0.006;

impl Controls {
    /// Applies one window event the UI did not take to `camera` (when it can move). Orbit and zoom
    /// turn about the point in focus on the view axis (`pivot`: the focus distance).
    pub fn event(&mut self, event: &WindowEvent, camera: &mut Camera, movable: bool, pivot: f32) {
        match event {
            WindowEvent::CursorMoved { position, .. } => {
                let now = (position.x, position.y);
                if let (Some(last), Some(start)) = (self.cursor, self.pressed_at) {
                    if (now.0 - start.0).abs() + (now.1 - start.1).abs() > 3.0 {
                        self.dragged = true;
                    }
                    if self.dragged && movable {
                        orbit(camera, (now.0 - last.0) as f32 * ORBIT_PER_PIXEL, (now.1 - last.1) as f32 * ORBIT_PER_PIXEL);
                    }
                }
                self.cursor = Some(now);
            }
            WindowEvent::MouseInput { state, button: MouseButton::Left, .. } => match state {
                ElementState::Pressed => {
                    self.pressed_at = self.cursor;
                    self.dragged = false;
                    if movable {
                        pivot_at(camera, pivot);
                    }
                }
                ElementState::Released => {
                    if !self.dragged {
                        self.focus_click = self.cursor;
                    }
                    self.pressed_at = None;
                }
            },
            WindowEvent::MouseInput { state: ElementState::Pressed, button: MouseButton::Right, .. } => self.focus_click = self.cursor,
            WindowEvent::MouseWheel { delta, .. } if movable => {
                let lines = match delta {
                    MouseScrollDelta::LineDelta(_, y) => *y,
                    MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
                };
                pivot_at(camera, pivot);
                zoom(camera, 0.9f32.powf(lines));
            }
            WindowEvent::KeyboardInput { event, .. } => {
                if let PhysicalKey::Code(code) = event.physical_key {
                    match event.state {
                        ElementState::Pressed => {
                            if self.held.insert(code) {
                                self.pressed.push(code);
                            }
                        }
                        ElementState::Released => {
                            self.held.remove(&code);
                        }
                    }
                }
            }
            WindowEvent::Focused(false) => self.held.clear(),
            _ => {}
        }
    }

    /// Flies the camera for `dt` seconds of the held keys; speed scales with the orbit distance.
    pub fn fly(&self, camera: &mut Camera, dt: f32) {
        let forward = camera.target - camera.eye;
        let distance = forward.length();
        if !(distance > 0.0) {
            return;
        }
        let forward = forward / distance;
        let right = forward.cross(camera.up).normalize_or_zero();
        let up = camera.up.normalize_or_zero();
        let mut step = Vec3::ZERO;
        for (key, dir) in [
            (KeyCode::KeyW, forward),
            (KeyCode::KeyS, -forward),
            (KeyCode::KeyD, right),
            (KeyCode::KeyA, -right),
            (KeyCode::KeyE, up),
            (KeyCode::KeyQ, -up),
        ] {
            if self.held.contains(&key) {
                step += dir;
            }
        }
        let step = step * (0.5 * distance * dt.min(0.25));
        camera.eye += step;
        camera.target += step;
    }
}

/// Moves the target along the view axis to `distance` from the eye (the view does not change: the
/// target only sets the axis), so that orbit and zoom turn about that point.
fn pivot_at(camera: &mut Camera, distance: f32) {
    let axis = (camera.target - camera.eye).normalize_or_zero();
    if axis != Vec3::ZERO && distance > 0.0 && distance.is_finite() {
        camera.target = camera.eye + axis * distance;
    }
}

/// Turns the eye about the target: `yaw` about the up axis, `pitch` about the right axis, kept
/// short of the poles (the up vector must not be parallel to the view axis).
pub fn orbit(camera: &mut Camera, yaw: f32, pitch: f32) {
    let up = camera.up.normalize_or_zero();
    let offset = camera.eye - camera.target;
    let distance = offset.length();
    if !(distance > 0.0) || up == Vec3::ZERO {
        return;
    }
    let dir = offset / distance;
    let elevation = dir.dot(up).clamp(-1.0, 1.0).asin();
    let new_elevation = (elevation + pitch).clamp(-1.45, 1.45);
    let flat = (dir - up * dir.dot(up)).normalize_or_zero();
    if flat == Vec3::ZERO {
        return;
    }
    let side = up.cross(flat);
    let (s, c) = (-yaw).sin_cos();
    let flat = flat * c + side * s;
    let dir = flat * new_elevation.cos() + up * new_elevation.sin();
    camera.eye = camera.target + dir * distance;
}

/// Moves the eye towards (`factor < 1`) or away from the target.
pub fn zoom(camera: &mut Camera, factor: f32) {
    let offset = camera.eye - camera.target;
    if offset.length() * factor > 1e-3 {
        camera.eye = camera.target + offset * factor;
    }
}

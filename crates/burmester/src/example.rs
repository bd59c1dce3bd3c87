//! The built-in example: a three-pose task and a driven crank whose branch
//! map shows both kinds of curve (a hyperbola and an ellipse). Used by the
//! command line, the benches and the docs.

use nalgebra::Point2;

use crate::geom::Viewport;
use crate::synthesis::Task;

/// The example's poses, `[x, y, angle]` with angles in radians.
pub const POSES: [[f64; 3]; 3] = [[0.0, 0.0, 0.0], [2.0, 0.5, 0.4], [3.0, 2.0, 1.1]];

/// The driven crank's fixed pivot `C0`.
pub const DRIVEN_CENTER: [f64; 2] = [4.0, -1.0];

/// The viewport of the example's center-point plane.
pub const VIEWPORT: [f64; 4] = [-8.0, 8.0, -8.0, 8.0];

/// The example task.
pub fn task() -> Task {
    Task::from_xya(&POSES).expect("the example task is valid")
}

/// The example's driven center point.
pub fn driven_center() -> Point2<f64> {
    Point2::new(DRIVEN_CENTER[0], DRIVEN_CENTER[1])
}

/// The example's viewport.
pub fn viewport() -> Viewport {
    let [a, b, c, d] = VIEWPORT;
    Viewport::new(a, b, c, d).expect("the example viewport is valid")
}

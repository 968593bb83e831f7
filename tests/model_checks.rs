//! Workspace-level checks of the model chain (MODEL-NOTES "Checks every implementation of the
//! chain should pass").

use ballscrew_core::{Model, ScrewSpec, SolverState};

#[test]
fn dkfzd4012_default_evaluates() {
    let spec = ScrewSpec::dkfzd4012();
    let model = Model::new(&spec).unwrap();
    let t = model.torque(&spec.operating, &mut SolverState::new()).unwrap();
    assert!(t > 0.0 && t.is_finite());
}

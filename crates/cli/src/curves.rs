//! The creep curves of one contact (`ballscrew creep-curves`, Fig. 9 of the paper), as the
//! command line holds them: each parameter from 0 to a span times its linear saturation value,
//! one curve per law, every point computed by the core
//! ([`ballscrew_core::contact::analysis::curve_point`]).

use crate::args::{ContactSetup, finite};
use crate::error::CliError;
use ballscrew_core::Error;
use ballscrew_core::contact::analysis::{CurvePoint, Law, Parameter, curve_point};

/// One curve: a parameter under a law.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The parameter varied.
    pub parameter: Parameter,
    /// The law.
    pub law: Law,
    /// The parameter's linear saturation value.
    pub saturation_value: f64,
    /// The points, by increasing value.
    pub points: Vec<CurvePoint>,
}

/// All curves of one contact: for each parameter, one curve per law.
#[derive(Debug, Clone, PartialEq)]
pub struct Curves {
    /// The contact.
    pub setup: ContactSetup,
    /// The laws, in order.
    pub laws: Vec<Law>,
    /// The span.
    pub span: f64,
    /// The curves, by parameter then law.
    pub curves: Vec<Curve>,
}

impl Curves {
    /// Evaluates every curve: `points` values (both ends included) from 0 to `span` times each
    /// parameter's linear saturation value.
    pub fn evaluate(setup: ContactSetup, laws: Vec<Law>, points: usize, span: f64) -> Result<Self, CliError> {
        let contact = &setup.contact;
        let mut curves = Vec::new();
        for parameter in Parameter::ALL {
            let saturation_value = contact.saturation_value(parameter);
            for &law in &laws {
                let name = match law {
                    Law::Fastsim(_) => "FASTSIM",
                    Law::Eq24 => "Eq. 24",
                };
                let values = (0..points).map(|i| span * saturation_value * i as f64 / (points - 1) as f64);
                let rows = values
                    .map(|value| {
                        let p = curve_point(contact, &setup.law, setup.grid, parameter, law, value)
                            .map_err(|e| CliError::eval(name, &Error::Input(e)))?;
                        finite(&p.forces, name)?;
                        Ok(p)
                    })
                    .collect::<Result<Vec<_>, CliError>>()?;
                curves.push(Curve { parameter, law, saturation_value, points: rows });
            }
        }
        Ok(Curves { setup, laws, span, curves })
    }

    /// The curves of one parameter.
    pub fn of(&self, parameter: Parameter) -> impl Iterator<Item = &Curve> {
        self.curves.iter().filter(move |c| c.parameter == parameter)
    }
}

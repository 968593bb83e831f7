//! One ball between screw and nut: its quasi-static balance (forces and moments of its two
//! raceway contacts and its neighbours) and the solvers that find it.
//!
//! - [`frames`]: global, Frenet-Serret and contact frames (Eqs. 1-2, corrected);
//! - [`setup`]: the unknowns and what a ball's balance depends on;
//! - [`lubrication`]: the lubricated raceway contacts (film, mixed friction, rolling
//!   resistance) of a ball in one solve;
//! - [`balance`]: the balance in lean form, generic over the float type (what Newton evaluates);
//! - [`report`]: the balance in report form, every intermediate of a ball's state kept (what
//!   reports show and checks compare);
//! - [`solve`]: the solvers of a ball's balance (Newton's method, the continuation in the
//!   friction coefficient and the creep stiffness, warm and predicted starts);
//! - [`four_point`]: the four-point contact ball of an oversize-ball nut (two contact
//!   diagonals, one ball) and its solver.
//!
//! It uses the contact layer ([`crate::contact`]) and the spec; nothing above it.

pub mod balance;
pub mod four_point;
pub mod frames;
pub mod lubrication;
pub mod report;
pub mod setup;
pub mod solve;

//! The point masks of the primal schemes, one file per scheme: [`catmark`] (Catmull–Clark),
//! [`loop`] (Loop), and [`crease`] for what both share: crease sharpness, its decay, the
//! crease and corner masks (with seed 002's circle-preserving weight) and the blend where a
//! semi-sharp feature runs out. The driver that applies them is [`crate::primal`]; the
//! splits that build the child's faces are in [`crate::refine`].

pub mod catmark;
pub mod crease;
pub mod r#loop;

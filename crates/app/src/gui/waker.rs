//! The window's repaint request as worker threads hold it.

use std::sync::Arc;

/// Asks the window for a repaint (from a worker thread).
pub type Waker = Arc<dyn Fn() + Send + Sync>;

//! The font of the command line's pictures (plots, labels): the one egui ships (Ubuntu Light),
//! registered with `plotters` once, so that nothing depends on the system's fonts.

use plotters::style::FontStyle;

/// The family name the pictures ask `plotters` for.
pub const FONT: &str = "sans-serif";

/// Registers [`FONT`] (once; later calls do nothing).
pub fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TrueType font (egui draws its whole UI with them).
        let _ = plotters::style::register_font(
            FONT,
            FontStyle::Normal,
            epaint_default_fonts::UBUNTU_LIGHT,
        );
    });
}

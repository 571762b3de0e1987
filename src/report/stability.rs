//! One visual language for the stability of an equilibrium, shared by the
//! branch diagrams and the phase portraits: three classes — stable (node or
//! focus), saddle, unstable (node, focus, or a degenerate point, which is
//! not asymptotically stable by its linearisation) — each with one colour,
//! one line style and one marker, and one word in every key.
//!
//! Stable is solid with a filled disc; a saddle is dashed with a diamond;
//! unstable is dotted with a hollow ring. The colours stay apart from the
//! phase portrait's trajectories and manifolds ([`TRAJECTORY`],
//! [`STABLE_MANIFOLD`], [`UNSTABLE_MANIFOLD`]).

use super::series::{Marker, Series, Shape, Style};

/// The stability class an equilibrium is drawn as.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Class {
    /// A stable node or focus.
    Stable,
    /// A saddle: one stable and one unstable direction.
    Saddle,
    /// An unstable node or focus, or a degenerate equilibrium.
    Unstable,
}

/// Palette index of the phase portrait's trajectories (light, behind).
pub const TRAJECTORY: usize = 8;
/// Palette index of a saddle's stable manifold, the separatrix.
pub const STABLE_MANIFOLD: usize = 4;
/// Palette index of a saddle's unstable manifold.
pub const UNSTABLE_MANIFOLD: usize = 5;

impl Class {
    /// Every class, in the order of a key.
    pub const ALL: [Class; 3] = [Class::Stable, Class::Saddle, Class::Unstable];

    /// Its word in a key.
    pub fn label(self) -> &'static str {
        match self {
            Class::Stable => "stable",
            Class::Saddle => "saddle",
            Class::Unstable => "unstable",
        }
    }

    /// Its palette index: blue, orange, red.
    pub fn colour(self) -> usize {
        match self {
            Class::Stable => 0,
            Class::Saddle => 3,
            Class::Unstable => 1,
        }
    }

    /// The line of a branch of this class.
    pub fn line(self) -> Style {
        match self {
            Class::Stable => Style::Line,
            Class::Saddle => Style::Dashed,
            Class::Unstable => Style::Dotted,
        }
    }

    /// The marker of an equilibrium of this class, radius `size` px.
    pub fn marker(self, size: u32) -> Marker {
        let shape = match self {
            Class::Stable => Shape::Disc,
            Class::Saddle => Shape::Diamond,
            Class::Unstable => Shape::Ring,
        };
        Marker { shape, size }
    }

    /// The class a segment between equilibria of classes `self` and `other`
    /// is drawn in: the less stable one (a segment is solid only when both
    /// ends are stable).
    pub fn weaker(self, other: Class) -> Class {
        self.max(other)
    }
}

/// A branch segment (or polyline) through `x`, `y` in the style of `class`,
/// without a key entry.
pub fn branch(class: Class, x: &[f64], y: &[f64]) -> Series {
    Series::line("", x, y, class.colour()).styled(class.line())
}

/// Equilibria at `x`, `y` marked as `class` (radius `size` px), without a
/// key entry.
pub fn equilibria(class: Class, x: &[f64], y: &[f64], size: u32) -> Series {
    Series::line("", x, y, class.colour())
        .styled(Style::Points(size))
        .marked(class.marker(size))
}

/// The key entry of `class`: its line with its marker on it, labelled with
/// its word.
pub fn key(class: Class) -> Series {
    Series::line(class.label(), &[], &[], class.colour())
        .styled(class.line())
        .marked(class.marker(5))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_classes_look_different() {
        // Colour, line and marker each tell the three apart.
        for (i, a) in Class::ALL.iter().enumerate() {
            for b in &Class::ALL[i + 1..] {
                assert_ne!(a.colour(), b.colour());
                assert_ne!(a.line(), b.line());
                assert_ne!(a.marker(5).shape, b.marker(5).shape);
            }
            assert!(![TRAJECTORY, STABLE_MANIFOLD, UNSTABLE_MANIFOLD].contains(&a.colour()));
        }
        assert_eq!(Class::Stable.line(), Style::Line);
        assert_eq!(Class::Stable.weaker(Class::Saddle), Class::Saddle);
        assert_eq!(Class::Unstable.weaker(Class::Stable), Class::Unstable);
        let k = key(Class::Saddle);
        assert_eq!(
            (k.label.as_str(), k.style, k.marker.map(|m| m.shape)),
            ("saddle", Style::Dashed, Some(Shape::Diamond))
        );
    }
}

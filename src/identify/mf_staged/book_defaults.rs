//! Pacejka's (2012) Magic Formula 6.1 book defaults, as MFeval 4.0's
//! `PacejkaBook_Defaults.tir` gives them (the file's figures, its source
//! named): the value a coefficient the data do not determine is held at,
//! where no template or user says another. Dimensionless, as the `.tir`
//! file states each coefficient.

/// The Magic Formula 6.1 defaults of Pacejka (2012) as MFeval 4.0's
/// `PacejkaBook_Defaults.tir` gives them, for every coefficient a stage
/// fits.
#[rustfmt::skip]
pub(super) const PACEJKA_BOOK: &[(&str, f64)] = &[
    ("PCX1", 1.6), ("PDX1", 1.0), ("PDX2", -0.1), ("PDX3", 0.0), ("PEX1", 0.0),
    ("PEX2", 0.0), ("PEX3", 0.0), ("PEX4", 0.0), ("PKX1", 16.0), ("PKX2", 0.0),
    ("PKX3", 0.0), ("PHX1", 0.0), ("PHX2", 0.0), ("PVX1", 0.0), ("PVX2", 0.0),
    ("PPX1", 0.0), ("PPX2", 0.0), ("PPX3", 0.0), ("PPX4", 0.0), ("PCY1", 1.3),
    ("PDY1", 1.0), ("PDY2", -0.05), ("PDY3", 0.0), ("PEY1", 0.0), ("PEY2", 0.0),
    ("PEY3", 0.0), ("PEY4", 0.0), ("PEY5", 0.0), ("PKY1", -15.0), ("PKY2", 2.0),
    ("PKY3", 0.0), ("PKY4", 2.0), ("PKY5", 0.0), ("PKY6", -1.0), ("PKY7", 0.0),
    ("PHY1", 0.0), ("PHY2", 0.0), ("PVY1", 0.0), ("PVY2", 0.0), ("PVY3", 0.0),
    ("PVY4", 0.0), ("PPY1", 0.0), ("PPY2", 0.0), ("PPY3", 0.0), ("PPY4", 0.0),
    ("PPY5", 0.0), ("QBZ1", 10.0), ("QBZ2", 0.0), ("QBZ3", 0.0), ("QBZ4", 0.0),
    ("QBZ5", 0.0), ("QBZ9", 10.0), ("QBZ10", 0.0), ("QCZ1", 1.1), ("QDZ1", 0.12),
    ("QDZ2", 0.0), ("QDZ3", 0.0), ("QDZ4", 0.0), ("QDZ6", 0.0), ("QDZ7", 0.0),
    ("QDZ8", -0.05), ("QDZ9", 0.0), ("QDZ10", 0.0), ("QDZ11", 0.0), ("QEZ1", 0.0),
    ("QEZ2", 0.0), ("QEZ3", 0.0), ("QEZ4", 0.0), ("QEZ5", 0.0), ("QHZ1", 0.0),
    ("QHZ2", 0.0), ("QHZ3", 0.0), ("QHZ4", 0.0), ("PPZ1", 0.0), ("PPZ2", 0.0),
    ("RBX1", 8.3), ("RBX2", 5.0), ("RBX3", 0.0), ("RCX1", 0.9), ("REX1", 0.0),
    ("REX2", 0.0), ("RHX1", 0.0), ("RBY1", 4.9), ("RBY2", 2.2), ("RBY3", 0.0),
    ("RBY4", 0.0), ("RCY1", 1.0), ("REY1", 0.0), ("REY2", 0.0), ("RHY1", 0.0),
    ("RHY2", 0.0), ("RVY1", 0.0), ("RVY2", 0.0), ("RVY3", 0.0), ("RVY4", 20.0),
    ("RVY5", 2.0), ("RVY6", 10.0), ("SSZ1", 0.0), ("SSZ2", 0.0), ("SSZ3", 0.0),
    ("SSZ4", 0.0), ("QSX1", 0.0), ("QSX2", 0.0), ("QSX3", 0.0), ("QSX4", 5.0),
    ("QSX5", 1.0), ("QSX6", 10.0), ("QSX7", 0.0), ("QSX8", 0.0), ("QSX9", 0.4),
    ("QSX10", 0.0), ("QSX11", 5.0), ("QSX12", 0.0), ("QSX13", 0.0), ("QSX14", 0.0),
    ("PPMX1", 0.0), ("QSY1", 0.01), ("QSY2", 0.0), ("QSY3", 0.0004), ("QSY4", 4e-5),
    ("QSY5", 0.0), ("QSY6", 0.0), ("QSY7", 0.85), ("QSY8", -0.4),
];

/// Pacejka's (2012) book default of a fitted coefficient (module notes).
pub fn pacejka_book_default(name: &str) -> Option<f64> {
    PACEJKA_BOOK.iter().find(|(k, _)| *k == name).map(|e| e.1)
}

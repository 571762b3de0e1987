//! Readers with validation: TOML files (scenarios, tyres, vehicles) and CSV
//! files (measured runs, tyre rig data, `FORMATS.md`).
//!
//! Every error names the file, and where there is one the line and column,
//! the key or column, the value and why it is wrong. Inputs are only read.

mod axis_order;
pub mod campaign;
mod columns;
pub(crate) mod file_kind;
pub mod fitted_ranges;
mod limits;
pub mod paths;
pub mod rig;
mod rig_camber;
mod rig_checks;
mod rig_degrees;
pub use rig_degrees::{camber_in_degrees, STEEP_CAMBER};
mod rig_exchanged;
pub(crate) mod rig_rows;
mod rig_scale;
mod run;
mod run_ay_sign;
mod run_bank;
mod run_offset;
mod run_response;
pub use run_bank::steep_bank;
mod run_slope;
mod run_turning;
mod run_units;
mod run_yaw_scale;
pub use run_units::{unchecked_speed_unit, MAX_SPEED};
pub mod scenario;
mod schedule;
pub mod study;
pub mod sweep;
mod tables;
pub mod tir;
mod toml_file;

pub use crate::measured::MeasuredRun;
pub use columns::{read_columns, Columns, Slip};
pub(crate) use columns::{read_columns_with_bad_cells, unit_of, Layout};
pub use run::{
    read_run, read_run_declared, read_run_reading, read_run_with, AbsentColumn, AngleColumn,
    DeclaredBy, RunHeader, ABSURD_STEER, OPTIONAL_CHANNELS,
};
pub use scenario::{load_scenario, load_tyre, Scenario, ScenarioFile};
pub(crate) use tables::check_tyre_at_load;
pub use tables::load_tyre_with_ranges;
pub use toml_file::vehicle_keys::UnreadKey;
pub use toml_file::{load_toml, param_error, TomlSource};

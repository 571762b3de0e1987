//! A value a test suite computes once per test run and shares: the tests
//! that read the same synthetic campaign or diagnosis (half a minute of
//! both cores each) ask for it by key, the first computes it, any asking
//! meanwhile waits for that one computation, the rest read it.

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Values by key, each made once.
pub(crate) struct Memo<K, V> {
    made: Mutex<BTreeMap<K, Arc<OnceLock<V>>>>,
}

impl<K: Ord, V: Clone> Memo<K, V> {
    /// An empty memo (a `static`'s initialiser).
    pub(crate) const fn new() -> Self {
        Self {
            made: Mutex::new(BTreeMap::new()),
        }
    }

    /// The value of `key`, made by `make` if no test has asked for it yet.
    /// The map's lock is held only to find the key's cell, so different
    /// keys are made side by side.
    pub(crate) fn get(&self, key: K, make: impl FnOnce() -> V) -> V {
        let cell = self
            .made
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .entry(key)
            .or_default()
            .clone();
        cell.get_or_init(make).clone()
    }
}

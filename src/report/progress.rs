//! A progress line on the terminal for long jobs: a background thread prints
//! `label: done/total (percent) elapsed` to stderr every 200 ms while the job
//! runs, only when stderr is a terminal (CI logs stay clean).

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// A running progress display; the counter is shared with the workers.
pub struct Progress {
    counter: Arc<AtomicUsize>,
    stop: Arc<AtomicBool>,
    handle: Option<JoinHandle<()>>,
}

impl Progress {
    /// Starts a display for `total` units of work.
    pub fn start(label: &str, total: usize) -> Self {
        let counter = Arc::new(AtomicUsize::new(0));
        let stop = Arc::new(AtomicBool::new(false));
        let handle = std::io::stderr().is_terminal().then(|| {
            let (c, s, label) = (counter.clone(), stop.clone(), label.to_string());
            std::thread::spawn(move || {
                let t0 = Instant::now();
                while !s.load(Ordering::Relaxed) {
                    let n = c.load(Ordering::Relaxed);
                    let pct = 100.0 * n as f64 / total.max(1) as f64;
                    eprint!(
                        "\r{label}: {n}/{total} ({pct:.0} %) {:.1} s ",
                        t0.elapsed().as_secs_f64()
                    );
                    let _ = std::io::stderr().flush();
                    std::thread::sleep(Duration::from_millis(200));
                }
                eprintln!(
                    "\r{label}: {total}/{total} (100 %) {:.1} s ",
                    t0.elapsed().as_secs_f64()
                );
            })
        });
        Self {
            counter,
            stop,
            handle,
        }
    }

    /// The shared counter the workers increment.
    pub fn counter(&self) -> &AtomicUsize {
        &self.counter
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

//! A progress line on the terminal for long jobs: a background thread prints
//! `label: done/total (percent) elapsed` to stderr every 200 ms while the job
//! runs when stderr is a terminal; off one (CI logs stay clean) only a job
//! of [`LONG`] units or more says its size and a line every 10 s.

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Units of work from which a job off a terminal says its size and its
/// progress (in lines, every 10 s).
const LONG: usize = 100_000;

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
        let terminal = std::io::stderr().is_terminal();
        // Off a terminal (a log, a CI job) a long job says its size at the
        // start and a line every 10 s: a million-condition sweep printed
        // nothing for a minute.
        if !terminal && total >= LONG {
            let (c, s, label) = (counter.clone(), stop.clone(), label.to_string());
            eprintln!("{label}: 0/{total} (0 %) 0 s; a progress line every 10 s");
            let handle = std::thread::spawn(move || {
                let t0 = Instant::now();
                let mut said = 0.0;
                while !s.load(Ordering::Relaxed) {
                    let t = t0.elapsed().as_secs_f64();
                    if t >= said + 10.0 {
                        said = t;
                        let n = c.load(Ordering::Relaxed);
                        let pct = 100.0 * n as f64 / total as f64;
                        eprintln!("{label}: {n}/{total} ({pct:.0} %) {t:.0} s");
                    }
                    std::thread::sleep(Duration::from_millis(200));
                }
            });
            return Self {
                counter,
                stop,
                handle: Some(handle),
            };
        }
        let handle = terminal.then(|| {
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

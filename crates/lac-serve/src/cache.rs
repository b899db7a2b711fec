//! The canonical region maps already computed: they depend only on the slopes (and the
//! ratio) and the size, and a designer drags many times with the same ones.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex};

/// A map's parameters, bit for bit: α (or α0), α1, ratio, size.
pub(crate) type RegionKey = (u64, Option<u64>, Option<u64>, usize);

/// At most `capacity` answers, the oldest dropped first.
#[derive(Debug)]
pub(crate) struct RegionCache {
    capacity: usize,
    entries: Mutex<VecDeque<(RegionKey, Arc<str>)>>,
}

impl RegionCache {
    pub(crate) fn new(capacity: usize) -> Self {
        RegionCache {
            capacity,
            entries: Mutex::new(VecDeque::new()),
        }
    }

    /// The answer kept for `key`.
    pub(crate) fn get(&self, key: &RegionKey) -> Option<Arc<str>> {
        let entries = self.entries.lock().unwrap_or_else(|e| e.into_inner());
        entries
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| Arc::clone(v))
    }

    /// Keep `answer` for `key`.
    pub(crate) fn put(&self, key: RegionKey, answer: Arc<str>) {
        if self.capacity == 0 {
            return;
        }
        let mut entries = self.entries.lock().unwrap_or_else(|e| e.into_inner());
        if entries.iter().any(|(k, _)| *k == key) {
            return;
        }
        while entries.len() >= self.capacity {
            entries.pop_front();
        }
        entries.push_back((key, answer));
    }
}

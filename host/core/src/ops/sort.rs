//! Segmented sort of `(f32 key, u32 payload)` lists on any backend (kernels and the algorithm in
//! `dof_shaders::sort`). The plan is sized from the device: the largest workgroup-memory class from
//! its shared-memory limit, the global path recorded only when a list can exceed that class.

use crate::backend::{Backend, BufferId, RunKernel, push_words, with_buffers};
use crate::error::{Error, Result};
use dof_shaders::sort::{
    self, CLASS_CAPS, CLASSIFY, ClassifyParams, GLOBAL_CLASS, GLOBAL_LOCAL, GLOBAL_STEP, GLOBAL_STORE, LOCAL_BLOCK, MAX_GROUPS,
    NUM_CLASSES, PLAN, PlanParams, SHARED_CLASSES, SortParams, plan, pow2_ceil, sort_classify, sort_global_local, sort_global_step,
    sort_global_store, sort_plan, top_class_for,
};

/// Buffers and sizes of a segmented sort, allocated once for a maximum problem size.
pub struct SegmentedSort {
    max_segments: u32,
    max_elements: u32,
    max_list_len: u32,
    top_class: u32,
    /// One plan per frame in flight (reports read it after the frame), and the one that
    /// [`Self::record`] writes and [`Self::stats`] reads.
    plans: Vec<BufferId>,
    slot: usize,
    lists: BufferId,
    scratch: Option<(BufferId, BufferId)>,
    /// Whether the workgroup-memory classes sort each list with one invocation (a merge sort)
    /// rather than the bitonic network: where a workgroup's invocations run one after another
    /// ([`crate::backend::Limits::serial_invocations`]). Either gives the same order.
    pub serial: bool,
}

/// What one sort did, read back from the plan buffer (for reports; the GPU path never needs it).
#[derive(Clone, Debug, Default)]
pub struct SortStats {
    /// Lists per workgroup-memory class, indexed like [`CLASS_CAPS`].
    pub class_counts: Vec<u32>,
    /// Lists that took the global-memory path, and the longest of them.
    pub global_lists: u32,
    pub global_max_len: u32,
    /// Capacity of the largest class this device runs.
    pub top_class_cap: u32,
}

impl SegmentedSort {
    /// `max_list_len` bounds every list; when it exceeds the largest class the device's workgroup
    /// memory allows, the global path is recorded (its dispatches are empty in frames without such lists).
    pub fn new(backend: &mut dyn Backend, max_segments: u32, max_elements: u32, max_list_len: u32) -> Result<Self> {
        Self::in_flight(backend, max_segments, max_elements, max_list_len, 1)
    }

    /// The same for `frames` frames in flight: a plan for each (see [`Self::use_slot`]), the rest
    /// shared.
    pub fn in_flight(backend: &mut dyn Backend, max_segments: u32, max_elements: u32, max_list_len: u32, frames: u32) -> Result<Self> {
        let top_class = top_class_for(backend.limits().max_shared_bytes);
        if CLASS_CAPS[top_class as usize] * sort::BYTES_PER_ELEMENT > backend.limits().max_shared_bytes {
            return Err(Error::TooLarge {
                what: "workgroup memory of the smallest sort class".into(),
                size: (CLASS_CAPS[0] * sort::BYTES_PER_ELEMENT) as u64,
                limit: backend.limits().max_shared_bytes as u64,
            });
        }
        let lists_words = (NUM_CLASSES as u64 + 1) * max_segments.max(1) as u64;
        let mut sizes = vec![(lists_words, "sort/lists")];
        if max_list_len > CLASS_CAPS[top_class as usize] {
            sizes.extend([(max_elements as u64, "sort/scratch-keys"), (max_elements as u64, "sort/scratch-positions")]);
        }
        sizes.extend((0..frames.max(1)).map(|_| (plan::WORDS as u64, "sort/plan")));
        // A failure part way (device memory running out) frees what was made.
        let mut made = Vec::new();
        for &(words, label) in &sizes {
            match backend.create_buffer(words, label) {
                Ok(id) => made.push(id),
                Err(e) => {
                    made.into_iter().for_each(|id| backend.destroy_buffer(id));
                    return Err(e);
                }
            }
        }
        let shared = made.len() - frames.max(1) as usize;
        let scratch = (shared == 3).then(|| (made[1], made[2]));
        let plans = made[shared..].to_vec();
        let serial = backend.limits().serial_invocations;
        Ok(SegmentedSort { max_segments, max_elements, max_list_len, top_class, plans, slot: 0, lists: made[0], scratch, serial })
    }

    /// Makes [`Self::record`] write, and [`Self::stats`] read, the plan of frame-in-flight `slot`.
    pub fn use_slot(&mut self, slot: usize) {
        assert!(slot < self.plans.len(), "sort plan {slot} of {}", self.plans.len());
        self.slot = slot;
    }

    pub fn destroy(self, backend: &mut dyn Backend) {
        self.buffers().into_iter().for_each(|b| backend.destroy_buffer(b));
    }

    /// Every buffer the sort holds (for an owner that frees them with its own).
    pub fn buffers(&self) -> Vec<BufferId> {
        let scratch = self.scratch.map(|(k, p)| [k, p]);
        self.plans.iter().copied().chain([self.lists]).chain(scratch.into_iter().flatten()).collect()
    }

    /// The kernels [`Self::record`] may dispatch on this device.
    pub fn kernels(&self) -> Vec<&'static dof_shaders::KernelDesc> {
        let mut k: Vec<_> = SHARED_CLASSES[..=self.top_class as usize].to_vec();
        k.extend([&CLASSIFY, &PLAN]);
        if self.scratch.is_some() {
            k.extend([&GLOBAL_LOCAL, &GLOBAL_STEP, &GLOBAL_STORE]);
        }
        k
    }

    /// Device memory the sort holds, in bytes.
    pub fn bytes(&self) -> u64 {
        let lists = (NUM_CLASSES as u64 + 1) * self.max_segments.max(1) as u64;
        let scratch = if self.scratch.is_some() { 2 * self.max_elements as u64 } else { 0 };
        4 * (plan::WORDS as u64 * self.plans.len() as u64 + lists + scratch)
    }

    /// [`Self::bytes`] per buffer: the lists, the global path's scratch (when recorded), the plans.
    pub fn table(&self) -> Vec<(String, u64)> {
        let lists = (NUM_CLASSES as u64 + 1) * self.max_segments.max(1) as u64;
        let mut rows = vec![("sort/lists".to_string(), 4 * lists)];
        if self.scratch.is_some() {
            rows.push(("sort/scratch-keys, scratch-positions".to_string(), 8 * self.max_elements as u64));
        }
        rows.push(("sort/plan".to_string(), 4 * plan::WORDS as u64 * self.plans.len() as u64));
        rows
    }

    /// The global path's key scratch, when it is recorded. [`Self::record`] may be handed it as
    /// `keys_out`: the global path writes it only at its own lists' positions, and its last pass
    /// (which reads it no more) writes their sorted keys there.
    pub fn scratch_keys(&self) -> Option<BufferId> {
        self.scratch.map(|(keys, _)| keys)
    }

    /// Capacity of the largest workgroup-memory class on this device.
    pub fn top_class_cap(&self) -> u32 {
        CLASS_CAPS[self.top_class as usize]
    }

    /// Records the sort of `num_segments` lists described by `segments` (`[offset, len]` pairs) from
    /// `keys_in`/`values_in` into `keys_out`/`values_out` (distinct buffers; `keys_out` may be
    /// [`Self::scratch_keys`]). Lists must lie inside the
    /// buffers and be at most `max_list_len` long: the kernels check bounds, but a violated bound
    /// leaves that list unsorted.
    #[allow(clippy::too_many_arguments)]
    pub fn record(
        &self,
        backend: &mut dyn Backend,
        segments: BufferId,
        num_segments: u32,
        keys_in: BufferId,
        values_in: BufferId,
        keys_out: BufferId,
        values_out: BufferId,
    ) -> Result<()> {
        if num_segments > self.max_segments {
            return Err(Error::InvalidArgument(format!("{num_segments} lists exceed the {} this sort was sized for", self.max_segments)));
        }
        let (plan_buf, lists) = (self.plans[self.slot], self.lists);
        backend.fill(plan_buf, 0, plan::WORDS as u64, 0, "sort/clear")?;
        let classify = ClassifyParams { num_segments, top_class: self.top_class };
        let groups = num_segments.div_ceil(256).clamp(1, MAX_GROUPS);
        backend.run(sort_classify::Bindings { segments, plan: plan_buf, lists }, [groups, 1, 1], &classify, "sort/classify")?;
        backend.run(sort_plan::Bindings { plan: plan_buf }, [1, 1, 1], &PlanParams::default(), "sort/plan")?;

        // The class kernels are chosen at run time from the table, so they are bound by position
        // (their bindings, one list for every class, are those of `sort_shared_64::Bindings`).
        let io = [segments, plan_buf, lists, keys_in, values_in, keys_out, values_out];
        for class in 0..=self.top_class {
            let params = push_words(&SortParams { num_segments, class, k: 0, j: 0, serial: self.serial as u32 });
            let args = (plan::CLASS_ARGS + 3 * class) as u64;
            let label = format!("sort/shared-{}", CLASS_CAPS[class as usize]);
            backend.dispatch_indirect(SHARED_CLASSES[class as usize], plan_buf, args, &io, &params, &label)?;
        }

        let Some((scratch_keys, scratch_pos)) = self.scratch else { return Ok(()) };
        let params = |k, j| SortParams { num_segments, class: GLOBAL_CLASS, k, j, serial: 0 };
        let local = sort_global_local::Bindings { segments, plan: plan_buf, lists, keys_in, scratch_keys, scratch_pos };
        let step = sort_global_step::Bindings { segments, plan: plan_buf, lists, scratch_keys, scratch_pos };
        let block_args = plan::BLOCK_ARGS as u64;
        backend.run_indirect(local, plan_buf, block_args, &params(0, 0), "sort/global-blocks")?;
        let mut k = 2 * LOCAL_BLOCK;
        while k <= pow2_ceil(self.max_list_len) {
            let mut j = k / 2;
            while j >= LOCAL_BLOCK {
                backend.run_indirect(step, plan_buf, plan::STEP_ARGS as u64, &params(k, j), "sort/global-step")?;
                j /= 2;
            }
            backend.run_indirect(local, plan_buf, block_args, &params(k, 0), "sort/global-merge")?;
            k *= 2;
        }
        let store = sort_global_store::Bindings { segments, plan: plan_buf, lists, keys_in, values_in, scratch_pos, keys_out, values_out };
        backend.run_indirect(store, plan_buf, plan::ELEMENT_ARGS as u64, &params(0, 0), "sort/global-store")
    }

    /// Reads what the last recorded sort did (submits pending work).
    pub fn stats(&self, backend: &mut dyn Backend) -> Result<SortStats> {
        self.stats_of(backend, self.slot)
    }

    /// Reads what the sort last recorded into frame-in-flight `slot` did.
    pub fn stats_of(&self, backend: &mut dyn Backend, slot: usize) -> Result<SortStats> {
        let buf = *self.plans.get(slot).ok_or_else(|| Error::InvalidArgument(format!("no sort plan {slot}")))?;
        let words = backend.read_buffer(buf, 0, plan::WORDS as u64)?;
        Ok(SortStats {
            class_counts: words[..NUM_CLASSES as usize].to_vec(),
            global_lists: words[GLOBAL_CLASS as usize],
            global_max_len: words[plan::GLOBAL_MAX_LEN as usize],
            top_class_cap: self.top_class_cap(),
        })
    }
}

/// A sort problem on the host: keys, payloads and the `(offset, len)` of each list.
#[derive(Clone, Debug, Default)]
pub struct SortInput {
    pub keys: Vec<f32>,
    pub values: Vec<u32>,
    pub segments: Vec<(u32, u32)>,
}

impl SortInput {
    /// Checks that payloads match keys and every list lies inside them.
    pub fn validate(&self) -> Result<()> {
        if self.keys.len() != self.values.len() {
            return Err(Error::InvalidArgument(format!("{} keys but {} payloads", self.keys.len(), self.values.len())));
        }
        if self.keys.len() > u32::MAX as usize || self.segments.len() > u32::MAX as usize / 2 {
            return Err(Error::TooLarge { what: "sort input".into(), size: self.keys.len() as u64, limit: u32::MAX as u64 });
        }
        for (i, &(offset, len)) in self.segments.iter().enumerate() {
            if offset as u64 + len as u64 > self.keys.len() as u64 {
                return Err(Error::InvalidArgument(format!("list {i} ({offset}+{len}) runs past the {} keys", self.keys.len())));
            }
        }
        Ok(())
    }

    pub fn max_list_len(&self) -> u32 {
        self.segments.iter().map(|s| s.1).max().unwrap_or(0)
    }

    /// The reference result: every list stable-sorted by [`dof_shaders::keys::sort_key`]. Elements
    /// outside every list keep their input value (as on the backends, whose outputs start as copies).
    pub fn reference(&self) -> (Vec<f32>, Vec<u32>) {
        let mut keys = self.keys.clone();
        let mut values = self.values.clone();
        for &(offset, len) in &self.segments {
            let range = offset as usize..(offset + len) as usize;
            let mut pairs: Vec<(f32, u32)> =
                self.keys[range.clone()].iter().copied().zip(self.values[range.clone()].iter().copied()).collect();
            pairs.sort_by_key(|(k, _)| dof_shaders::keys::sort_key(k.to_bits()));
            for (i, (k, v)) in pairs.into_iter().enumerate() {
                keys[range.start + i] = k;
                values[range.start + i] = v;
            }
        }
        (keys, values)
    }
}

/// The result of [`sort_on`].
#[derive(Debug)]
pub struct SortOutput {
    pub keys: Vec<f32>,
    pub values: Vec<u32>,
    pub stats: SortStats,
    pub times: Vec<crate::backend::CommandTime>,
}

/// Uploads, sorts and reads back `input` on `backend`. Outputs start as copies of the inputs, so words
/// outside every list come back unchanged.
pub fn sort_on(backend: &mut dyn Backend, input: &SortInput) -> Result<SortOutput> {
    sort_on_with(backend, input, None)
}

/// [`sort_on`] with the workgroup-memory classes' strategy chosen ([`SegmentedSort::serial`]), or
/// the device's (`None`): for checking that both give the same order on every backend.
pub fn sort_on_with(backend: &mut dyn Backend, input: &SortInput, serial: Option<bool>) -> Result<SortOutput> {
    input.validate()?;
    let n = input.keys.len() as u64;
    let key_bits: Vec<u32> = input.keys.iter().map(|k| k.to_bits()).collect();
    let seg_words: Vec<u32> = input.segments.iter().flat_map(|&(o, l)| [o, l]).collect();
    let sizes = [
        (seg_words.len() as u64, "sort/segments"),
        (n, "sort/keys-in"),
        (n, "sort/values-in"),
        (n, "sort/keys-out"),
        (n, "sort/values-out"),
    ];
    with_buffers(backend, &sizes, |backend, b| {
        let (segments, keys_in, values_in, keys_out, values_out) = (b[0], b[1], b[2], b[3], b[4]);
        backend.write_buffer(segments, 0, &seg_words)?;
        backend.write_buffer(keys_in, 0, &key_bits)?;
        backend.write_buffer(values_in, 0, &input.values)?;
        backend.write_buffer(keys_out, 0, &key_bits)?;
        backend.write_buffer(values_out, 0, &input.values)?;
        let mut sort = SegmentedSort::new(backend, input.segments.len() as u32, n as u32, input.max_list_len())?;
        sort.serial = serial.unwrap_or(sort.serial);
        let recorded = sort.record(backend, segments, input.segments.len() as u32, keys_in, values_in, keys_out, values_out);
        let done = recorded.and_then(|_| backend.submit()).and_then(|times| {
            let stats = sort.stats(backend)?;
            let keys = backend.read_buffer(keys_out, 0, n)?.into_iter().map(f32::from_bits).collect();
            let values = backend.read_buffer(values_out, 0, n)?;
            Ok(SortOutput { keys, values, stats, times })
        });
        sort.destroy(backend);
        done
    })
}

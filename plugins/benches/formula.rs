//! What a formula label costs its plugin: typesetting a formula not seen before, against
//! taking one already typeset (the same text, colour and resolution: a label on every robot of
//! a swarm). Both through `typeset`, as the formula plugin calls it.
//!
//! `cargo bench -p plugins --bench formula -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use framework::scene::Rgba;
use plugins::formula::typeset::{DEFAULT_DPI, typeset};

fn formula(c: &mut Criterion) {
    let mut group = c.benchmark_group("formula");
    let mut n = 0u64;
    group.bench_function("new formula", |b| {
        b.iter(|| {
            n += 1;
            // A number no earlier iteration wrote: typeset from scratch each time.
            let text = format!(r"$v_{{{n}}} = \omega r$");
            black_box(typeset(&text, Rgba::WHITE, DEFAULT_DPI).unwrap())
        })
    });
    let known = r"$v = \omega r$";
    typeset(known, Rgba::WHITE, DEFAULT_DPI).unwrap();
    group.bench_function("formula typeset before", |b| {
        b.iter(|| black_box(typeset(black_box(known), Rgba::WHITE, DEFAULT_DPI).unwrap()))
    });
    group.finish();
}

criterion_group!(benches, formula);
criterion_main!(benches);

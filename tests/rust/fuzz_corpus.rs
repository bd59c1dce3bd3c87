//! The fuzz targets' checks (`fuzz/src/lib.rs`) replayed on the committed
//! corpus and on every finding, without libFuzzer: each file under
//! `fuzz/regressions/<target>/` is an input that once failed (named after
//! the bug), and `fuzz/corpus/<target>/` is a small corpus that covers the
//! target. The long fuzzing runs stay outside CI (see `fuzz/README.md`).

use std::path::Path;

#[allow(unreachable_pub, dead_code)]
#[path = "../../fuzz/src/lib.rs"]
mod checks;

fn replay(target: &str, check: fn(&[u8])) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let mut count = 0;
    for dir in ["regressions", "corpus"] {
        let Ok(entries) = std::fs::read_dir(root.join(dir).join(target)) else {
            continue;
        };
        let mut files: Vec<_> = entries.filter_map(|e| e.ok()).map(|e| e.path()).collect();
        files.sort();
        for f in files {
            let data = std::fs::read(&f).unwrap();
            let name = f.display().to_string();
            let r = std::panic::catch_unwind(|| check(&data));
            assert!(r.is_ok(), "{target}: {name} fails");
            count += 1;
        }
    }
    assert!(count > 0, "{target}: no corpus files found");
}

/// One test per fuzz target, named after it, replaying its files through
/// its check.
macro_rules! replay_targets {
    ($($target:ident),* $(,)?) => {$(
        #[test]
        fn $target() {
            replay(stringify!($target), checks::$target);
        }
    )*};
}

replay_targets!(
    fourbar,
    task_maps,
    filemon_classify,
    conic,
    solution_map,
    conic_polylines,
    curves,
    burmester_points,
    pair_map,
    atlas,
);

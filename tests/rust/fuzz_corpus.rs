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

/// The open findings (`fuzz/open/<target>/`, see `fuzz/README.md`) replayed
/// through their target's check: prints which still fail. Not a gate (they
/// are open), so ignored: `cargo test --test fuzz_corpus -- --ignored
/// --nocapture open_findings`. `FUZZ_FINDINGS=regressions` replays (and
/// dumps the five-pose answers of) `fuzz/regressions/` instead, for
/// `fuzz/reference/balance_five.py`.
#[test]
#[ignore]
fn open_findings() {
    let dir = std::env::var("FUZZ_FINDINGS").unwrap_or_else(|_| "open".to_string());
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fuzz")
        .join(dir);
    type Check = fn(&[u8]);
    let targets: [(&str, Check); 2] = [
        ("curves", checks::curves),
        ("burmester_points", checks::burmester_points),
    ];
    for (target, check) in targets {
        let Ok(entries) = std::fs::read_dir(root.join(target)) else {
            continue;
        };
        let mut files: Vec<_> = entries.filter_map(|e| e.ok()).map(|e| e.path()).collect();
        files.sort();
        let mut failing = 0;
        for f in &files {
            let data = std::fs::read(f).unwrap();
            let ok = std::panic::catch_unwind(|| check(&data)).is_ok();
            failing += usize::from(!ok);
            println!(
                "{target}: {} {}",
                f.display(),
                if ok { "passes" } else { "fails" }
            );
            if target == "burmester_points" {
                five_answers(&data);
            }
        }
        println!("{target}: {failing} of {} fail", files.len());
    }
}

/// A `burmester_points` input's task and its moved frame, each with the
/// library's answer, one line each (for the exact reference:
/// `fuzz/reference/open_five.py` reads these lines).
fn five_answers(data: &[u8]) {
    use burmester::synthesis::FivePositions;
    let (poses, t) = checks::burmester_points_task(data);
    let show = |name: &str, q: &[burmester::Pose]| {
        let xya: Vec<(f64, f64, f64)> = q
            .iter()
            .map(|p| (p.position.x, p.position.y, p.angle))
            .collect();
        let answer = match FivePositions::new(q) {
            Ok(f) => {
                let c: Vec<(f64, f64)> = f
                    .burmester_points()
                    .iter()
                    .map(|d| (d.center.x, d.center.y))
                    .collect();
                format!("points {c:?} sliders {}", f.sliders().len())
            }
            Err(e) => format!("error {e}"),
        };
        println!("  {name} {xya:?}\n    {answer}");
    };
    show("task", &poses);
    if let Ok(t) = t {
        let moved: Vec<burmester::Pose> = poses.iter().map(|q| t.pose(q)).collect();
        show("moved", &moved);
    }
}

use super::*;
use std::sync::Arc;

static NEVER: AtomicBool = AtomicBool::new(false);

#[test]
fn a_step_waits_for_every_present_driver() {
    let lockstep = Lockstep::new(Some(Duration::from_secs(30)));
    lockstep.commanded(1);
    lockstep.commanded(2);
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Answered));
    lockstep.stepped();
    lockstep.commanded(1);
    let shared = Arc::new(lockstep);
    let stepper = {
        let shared = shared.clone();
        std::thread::spawn(move || shared.next_step(&NEVER))
    };
    std::thread::sleep(Duration::from_millis(100));
    assert!(!stepper.is_finished(), "driver 2 has not answered");
    shared.commanded(2);
    assert_eq!(stepper.join().unwrap(), Some(StepCause::Answered));
}

#[test]
fn a_late_driver_is_named_then_not_waited_for() {
    let lockstep = Lockstep::new(Some(Duration::from_millis(50)));
    lockstep.commanded(7);
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Answered));
    lockstep.stepped();
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Late(vec![7])));
    lockstep.stepped();
    let started = Instant::now();
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Alone));
    assert!(
        started.elapsed() < Duration::from_millis(40),
        "an absent driver is not waited for"
    );
    lockstep.commanded(7);
    lockstep.stepped();
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Late(vec![7])));
}

#[test]
fn without_drivers_the_patience_passes_once_then_steps_go() {
    let lockstep = Lockstep::new(Some(Duration::from_millis(30)));
    let started = Instant::now();
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Alone));
    assert!(started.elapsed() >= Duration::from_millis(30));
    lockstep.stepped();
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Alone));
}

#[test]
fn a_connection_while_nobody_drives_restarts_the_wait() {
    let lockstep = Lockstep::new(Some(Duration::from_millis(100)));
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Alone));
    lockstep.stepped();
    lockstep.arrived();
    let started = Instant::now();
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Alone));
    assert!(
        started.elapsed() >= Duration::from_millis(100),
        "the newcomer had its patience"
    );
}

#[test]
fn a_command_sent_just_before_leaving_still_takes_its_step() {
    let lockstep = Arc::new(Lockstep::new(Some(Duration::from_secs(30))));
    lockstep.commanded(4);
    lockstep.left(4);
    assert!(!lockstep.settled(), "its step is owed");
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Answered));
    lockstep.stepped();
    let waiting = {
        let lockstep = lockstep.clone();
        std::thread::spawn(move || lockstep.next_step(&NEVER))
    };
    let deadline = Instant::now() + Duration::from_secs(5);
    while !lockstep.settled() {
        assert!(Instant::now() < deadline, "settles once the step is taken");
        std::thread::sleep(Duration::from_millis(5));
    }
    lockstep.release(1);
    assert_eq!(waiting.join().unwrap(), Some(StepCause::Released));
}

#[test]
fn released_steps_go_and_a_stop_ends_the_wait() {
    let lockstep = Lockstep::new(None);
    lockstep.release(2);
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Released));
    lockstep.stepped();
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Released));
    lockstep.stepped();
    assert!(lockstep.wait_for_step(2, Duration::ZERO));
    let stop = AtomicBool::new(true);
    assert_eq!(lockstep.next_step(&stop), None);
}

#[test]
fn a_driver_that_leaves_is_not_waited_for() {
    let lockstep = Lockstep::new(None);
    lockstep.commanded(1);
    lockstep.commanded(2);
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Answered));
    lockstep.stepped();
    lockstep.commanded(1);
    lockstep.left(2);
    assert_eq!(lockstep.next_step(&NEVER), Some(StepCause::Answered));
}

#[test]
fn a_second_command_in_a_step_waits_for_the_step() {
    let lockstep = Arc::new(Lockstep::new(None));
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .unwrap();
    runtime.block_on(async {
        lockstep.turn(3).await; // not a driver yet: at once
        lockstep.commanded(3);
        let held = tokio::time::timeout(Duration::from_millis(50), lockstep.turn(3)).await;
        assert!(held.is_err(), "answered already: waits for the step");
        let stepper = {
            let lockstep = lockstep.clone();
            std::thread::spawn(move || {
                lockstep.next_step(&NEVER);
                lockstep.stepped();
            })
        };
        tokio::time::timeout(Duration::from_secs(5), lockstep.turn(3))
            .await
            .expect("the step was taken");
        stepper.join().unwrap();
    });
}

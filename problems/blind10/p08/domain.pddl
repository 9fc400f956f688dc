;; blind10 p08: a heavy crate is shoved (never lifted: only small things
;; have a grab action), small things are grabbed and stowed. A shove goes
;; from one zone through a via zone into another, and needs both the via
;; zone and the target cleared: nothing standing in them. Each zone holds
;; at most one thing, so grabbing a thing clears its zone.
(define (domain blind10-clear)
  (:requirements :strips :typing)
  (:types crate small - thing
          thing zone)
  (:predicates (located ?t - thing ?z - zone)
               (cleared ?z - zone)
               (between ?from - zone ?via - zone ?to - zone)
               (dock ?z - zone)
               (top-free ?c - crate)
               (on-top ?s - small ?c - crate)
               (holds ?s - small)
               (free-gripper))
  (:action grab
    :parameters (?s - small ?z - zone)
    :precondition (and (located ?s ?z) (free-gripper))
    :effect (and (not (located ?s ?z)) (cleared ?z) (not (free-gripper))
                 (holds ?s)))
  (:action stow
    :parameters (?s - small ?z - zone)
    :precondition (and (holds ?s) (cleared ?z))
    :effect (and (not (holds ?s)) (free-gripper) (located ?s ?z)
                 (not (cleared ?z))))
  (:action shove
    :parameters (?c - crate ?from - zone ?via - zone ?to - zone)
    :precondition (and (located ?c ?from) (between ?from ?via ?to)
                       (cleared ?via) (cleared ?to) (free-gripper))
    :effect (and (not (located ?c ?from)) (cleared ?from)
                 (located ?c ?to) (not (cleared ?to))))
  (:action perch
    :parameters (?s - small ?c - crate ?z - zone)
    :precondition (and (holds ?s) (located ?c ?z) (dock ?z) (top-free ?c))
    :effect (and (not (holds ?s)) (free-gripper) (on-top ?s ?c)
                 (not (top-free ?c)))))

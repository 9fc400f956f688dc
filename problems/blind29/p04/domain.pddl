; blind29 p04: lock and key (MiniGrid's DoorKey, made geometric). A prize
; stands in a locker whose mouth is screened by a sliding screen (a
; push-only panel). The screen slides only once unlocked, and it is unlocked
; by setting the right key down on the lock pad (a conditional effect of
; place, quantified over doors). Typed with subtypes, :conditional-effects,
; negative preconditions, :equality.
(define (domain b29-locker)
  (:requirements :strips :typing :negative-preconditions :equality
                 :conditional-effects :universal-preconditions)
  (:types item door zone - object
          key prize - item)
  (:predicates (at ?o - item ?z - zone) (door-at ?d - door ?z - zone)
               (holding ?o - item) (hand-empty)
               (lock-pad ?z - zone) (opens ?k - item ?d - door)
               (unlocked ?d - door) (slides-to ?d - door ?z - zone))

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (hand-empty))
    :effect (and (not (at ?o ?z)) (holding ?o) (not (hand-empty))))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (hand-empty) (not (holding ?o))
                 (forall (?d - door)
                   (when (and (lock-pad ?z) (opens ?o ?d)) (unlocked ?d)))))

  (:action slide
    :parameters (?d - door ?from ?to - zone)
    :precondition (and (door-at ?d ?from) (unlocked ?d) (hand-empty)
                       (slides-to ?d ?to) (not (= ?from ?to)))
    :effect (and (not (door-at ?d ?from)) (door-at ?d ?to))))

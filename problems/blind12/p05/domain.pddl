;; blind12 p05: a key is drawn out of one slot and slid into another.
(define (domain blind12-slots)
  (:requirements :strips :typing)
  (:types key slot)
  (:predicates (seated ?k - key ?s - slot)
               (gripped ?k - key)
               (open-hand))
  (:action draw-out
    :parameters (?k - key ?s - slot)
    :precondition (and (seated ?k ?s) (open-hand))
    :effect (and (gripped ?k) (not (seated ?k ?s)) (not (open-hand))))
  (:action slide-in
    :parameters (?k - key ?s - slot)
    :precondition (gripped ?k)
    :effect (and (seated ?k ?s) (open-hand) (not (gripped ?k)))))

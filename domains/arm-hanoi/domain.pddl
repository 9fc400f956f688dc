; Tower of Hanoi with a Franka Panda: flat discs on three fixed platforms.
; A move is pick + place; a disc may only go onto an empty platform or a
; larger disc. With n discs the only optimal plan has 2^n - 1 moves.
(define (domain arm-hanoi)
  (:requirements :strips :typing)
  (:types thing - object
          disc platform - thing)
  (:predicates (on ?d - disc ?x - thing)
               (clear ?x - thing)
               (larger ?x - thing ?d - disc)   ; ?d may rest on ?x
               (holding ?d - disc)
               (handempty))

  (:action pick
    :parameters (?d - disc ?from - thing)
    :precondition (and (on ?d ?from) (clear ?d) (handempty))
    :effect (and (not (on ?d ?from)) (not (clear ?d)) (not (handempty))
                 (holding ?d) (clear ?from)))

  (:action place
    :parameters (?d - disc ?to - thing)
    :precondition (and (holding ?d) (clear ?to) (larger ?to ?d))
    :effect (and (not (holding ?d)) (not (clear ?to)) (handempty)
                 (clear ?d) (on ?d ?to))))
